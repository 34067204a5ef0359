using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        // Shapes on bodies with continuous collision; the stage returns at once while it is 0.
        int _ccdShapeCount;

        /// <summary>Shapes on bodies with continuous collision (0 means the stage is skipped).</summary>
        internal int CcdShapeCount => _ccdShapeCount;

        void OnCcdShapeAdded(int body)
        {
            if (Bodies.Ccd[body]) _ccdShapeCount++;
        }

        void OnCcdShapeRemoved(int body)
        {
            if (Bodies.Ccd[body]) _ccdShapeCount--;
        }

        /// <summary>Turns continuous collision of a body on or off, keeping the count of CCD shapes.</summary>
        internal void SetCcd(int body, bool on)
        {
            if (Bodies.Ccd[body] == on) return;
            int shapes = 0;
            for (int s = Bodies.FirstShape[body]; s >= 0; s = Shapes.NextInBody[s]) shapes++;
            _ccdShapeCount += on ? shapes : -shapes;
            Bodies.Ccd[body] = on;
        }

        /// <summary>
        /// Continuous collision, after the solver moved the bodies: each awake dynamic body
        /// that asked for it (<see cref="BodyDef.Ccd"/>) and moved more than half its
        /// thinnest shape's thickness in the step is swept from its start pose to its end
        /// pose against every other shape in reach; if it would have touched one on the way, it
        /// is put back where it first comes within <see cref="CollisionMargins.CcdTargetFactor"/>
        /// slop of it (velocity kept, so the next step's speculative contact meets it).
        /// <see cref="StepStage.Continuous"/> then checks every body for divergence (the last
        /// stage that moves bodies is over). Reads: start and end poses, the broad-phase trees,
        /// shape geometry. Writes: the poses of swept bodies (and their world inertia); diverged
        /// bodies are put back and reported (<see cref="Diverged"/>).
        /// </summary>
        void Continuous(float dt)
        {
            if (_ccdShapeCount != 0) SweepContinuousBodies();
            CheckDivergence();
        }

        void SweepContinuousBodies()
        {
            BodyStorage b = Bodies;
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                if (!b.Ccd[i] || b.Type[i] != BodyType.Dynamic || !b.Awake[i]) continue;
                SweepBody(i);
            }
        }

        void SweepBody(int body)
        {
            BodyStorage b = Bodies;
            var sweep = new BodySweep
            {
                Center0 = b.PreviousPosition[body] + Vector3.Transform(b.LocalCenter[body], b.PreviousRotation[body]),
                Center1 = b.Center[body],
                Rotation0 = b.PreviousRotation[body],
                Rotation1 = b.Rotation[body],
                LocalCenter = b.LocalCenter[body],
            };
            if (Quaternion.Dot(sweep.Rotation0, sweep.Rotation1) < 0) sweep.Rotation1 = Quaternion.Negate(sweep.Rotation1);

            // Only fast bodies: slower ones are met by speculative contacts.
            float thickness = float.MaxValue, reach = 0;
            Pose start = sweep.BodyPose(0);
            for (int s = b.FirstShape[body]; s >= 0; s = Shapes.NextInBody[s])
            {
                if (Shapes.IsSensor[s]) continue;
                thickness = MathF.Min(thickness, Thickness(Shapes.Geometry[s]));
                Aabb box = Shapes.Geometry[s].ComputeAabb(start * Shapes.LocalPose[s]);
                reach = MathF.Max(reach, Vector3.Distance(box.Center, sweep.Center0) + box.Extents.Length());
            }
            if (thickness == float.MaxValue) return;
            float bound = sweep.MotionBound(reach);
            if (bound < 0.5f * thickness) return;

            float slop = _settings.LinearSlop;
            var finder = new CcdCandidates
            {
                World = this,
                Body = body,
                Sweep = sweep,
                Bound = bound,
                TargetGap = CollisionMargins.CcdTargetFactor * slop,
                Tolerance = 0.25f * slop,
                FastApproach = 0.5f * thickness,
                Toi = 1,
            };
            float angular = sweep.Angle * reach;
            Pose end = sweep.BodyPose(1);
            for (int s = b.FirstShape[body]; s >= 0; s = Shapes.NextInBody[s])
            {
                if (Shapes.IsSensor[s]) continue;
                finder.Shape = s;
                Aabb a0 = Shapes.Geometry[s].ComputeAabb(start * Shapes.LocalPose[s]);
                Aabb a1 = Shapes.Geometry[s].ComputeAabb(end * Shapes.LocalPose[s]);
                Aabb swept = Aabb.Union(a0, a1).Expanded(angular + finder.TargetGap);
                finder.Swept = swept;
                _broadPhase.StaticTree.Query(swept, ref finder);
                _broadPhase.MovingTree.Query(swept, ref finder);
            }
            if (finder.Toi >= 1) return;

            Pose at = sweep.BodyPose(finder.Toi);
            b.Position[body] = at.Position;
            b.Rotation[body] = at.Rotation;
            b.SyncCenterFromOrigin(body);
            AxisLocks locks = b.Locks[body] & AxisLocks.Linear;
            if (locks != 0)
            {
                // The sweep interpolates the centre; along a locked axis it must stay exactly
                // where the solver left it, not a rounding of it.
                Vector3 c = b.Center[body], c1 = sweep.Center1;
                if ((locks & AxisLocks.LinearX) != 0) c.X = c1.X;
                if ((locks & AxisLocks.LinearY) != 0) c.Y = c1.Y;
                if ((locks & AxisLocks.LinearZ) != 0) c.Z = c1.Z;
                b.Center[body] = c;
                b.SyncOriginFromCenter(body);
            }
            b.UpdateWorldInertia(body);
        }

        /// <summary>
        /// The time of impact of one shape of a CCD body against another shape (at its end
        /// pose), or 1 when none comes before <paramref name="tMax"/>. Filtered like contact pairs.
        /// </summary>
        internal float ShapeTimeOfImpact(int shape, int other, in BodySweep sweep, float bound, float targetGap, float tolerance, float fastApproach, float tMax, in Aabb swept)
        {
            ShapeStorage s = Shapes;
            int bodyA = s.Body[shape], bodyB = s.Body[other];
            if (bodyA == bodyB || s.IsSensor[other]) return 1;
            if ((s.CollidesWith[shape] & (1u << s.Layer[other])) == 0 || (s.CollidesWith[other] & (1u << s.Layer[shape])) == 0) return 1;
            if (IgnoresPair(shape, other)) return 1;
            ShapeGeometry g = s.Geometry[shape];
            Pose local = s.LocalPose[shape];
            ShapeGeometry target = s.Geometry[other];
            Pose targetPose = ShapeWorldPose(other);
            float toi;
            switch (target.Type)
            {
                case ShapeType.Plane:
                {
                    Vector3 n = targetPose.TransformDirection(target.Normal);
                    float offset = Vector3.Dot(n, targetPose.TransformPoint(target.Normal * target.Offset));
                    return TimeOfImpact.Compute(g, local, sweep, bound, default, true, n, offset, targetGap, tolerance, fastApproach, tMax, out toi) ? toi : 1;
                }
                case ShapeType.TriangleMesh:
                {
                    var visitor = new CcdTriangles
                    {
                        Mesh = (TriangleMesh)target.Data!,
                        MeshPose = targetPose,
                        Geometry = g,
                        LocalPose = local,
                        Sweep = sweep,
                        Bound = bound,
                        TargetGap = targetGap,
                        Tolerance = tolerance,
                        FastApproach = fastApproach,
                        Toi = tMax,
                    };
                    Pose inverse = targetPose.Inverse();
                    Aabb localBox = Aabb.Transform(inverse, swept.Center, swept.Extents);
                    visitor.Mesh.Bvh.Query(localBox, ref visitor);
                    return visitor.Toi < tMax ? visitor.Toi : 1;
                }
                default:
                    return TimeOfImpact.Compute(g, local, sweep, bound, SupportShape.From(target, targetPose), false, default, 0,
                        targetGap, tolerance, fastApproach, tMax, out toi) ? toi : 1;
            }
        }

        // How thin a shape is: the distance its surface can move before it could have
        // passed something of zero thickness.
        static float Thickness(in ShapeGeometry g)
        {
            switch (g.Type)
            {
                case ShapeType.Sphere:
                case ShapeType.Capsule:
                    return 2 * g.Radius;
                case ShapeType.Box:
                    return 2 * MathF.Min(g.HalfExtents.X, MathF.Min(g.HalfExtents.Y, g.HalfExtents.Z));
                case ShapeType.ConvexHull:
                {
                    var hull = (ConvexHull)g.Data!;
                    float min = float.MaxValue;
                    for (int f = 0; f < hull.FaceCount; f++)
                        min = MathF.Min(min, hull.FaceOffsets[f] - Vector3.Dot(hull.FaceNormals[f], hull.Centroid));
                    return 2 * min;
                }
                default:
                    return float.MaxValue;
            }
        }
    }
}
