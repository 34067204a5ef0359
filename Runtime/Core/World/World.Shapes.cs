using System;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Attaches a shape to a body; the body's mass is recomputed from its shapes unless it
        /// was set directly. Planes and meshes may only go on static bodies. Checked before
        /// anything changes.
        /// </summary>
        public ShapeHandle AddShape(BodyHandle body, in ShapeDef def)
        {
            ThrowIfInStep();
            int b = Slot(body);
            def.Validate();
            if (def.Geometry.IsStaticOnly && Bodies.Type[b] != BodyType.Static)
                throw new ArgumentException($"A {def.Geometry.Type} shape can only be attached to a static body; {Describe(b)} is {Bodies.Type[b]}.", nameof(def));
            var localPose = new Pose(def.LocalPose.Position, Validate.Rotation(def.LocalPose.Rotation, "shape.LocalPose.Rotation"));
            CheckMassWith(b, def, localPose);

            ShapeStorage s = Shapes;
            int i = s.Allocate();
            s.Geometry[i] = def.Geometry;
            s.LocalPose[i] = localPose;
            s.Body[i] = b;
            s.Density[i] = def.Density;
            s.Friction[i] = def.Friction;
            s.Restitution[i] = def.Restitution;
            s.FrictionCombine[i] = def.FrictionCombine;
            s.RestitutionCombine[i] = def.RestitutionCombine;
            s.IsSensor[i] = def.IsSensor;
            s.Layer[i] = def.Layer;
            s.CollidesWith[i] = def.CollidesWith;
            s.UserData[i] = def.UserData;
            s.NextInBody[i] = Bodies.FirstShape[b];
            Bodies.FirstShape[b] = i;
            s.WorldAabb[i] = def.Geometry.ComputeAabb(ShapeWorldPose(i));
            OnShapeAdded(i);
            UpdateMassProperties(b);
            return new ShapeHandle(i, s.Generation[i], Id);
        }

        // The body's mass with the new shape, checked before anything changes, so a shape whose
        // mass or inertia overflows (a 1e13 m box) or leaves the documented range is refused
        // with the body as it was.
        void CheckMassWith(int b, in ShapeDef def, in Pose localPose)
        {
            if (Bodies.Type[b] != BodyType.Dynamic || Bodies.MassOverride[b] < 0 || def.IsSensor || def.Density <= 0) return;
            MassProperties m = def.Geometry.ComputeMass(def.Density).Transformed(localPose);
            // Each shape on its own within the range too, so that removing the others later
            // cannot leave a body lighter than Limits.MinMass.
            if (Bodies.MassOverride[b] == 0 && def.Geometry.Type != ShapeType.Plane && def.Geometry.Type != ShapeType.TriangleMesh)
                Limits.CheckMass(m.Mass, "shape.Density (this shape's mass)");
            MassProperties total = ShapeMass(b);
            if (total.Mass > 0 && m.Mass > 0) total = MassProperties.Combine(total, m);
            else if (m.Mass > 0) total = m;
            else return;
            if (Bodies.MassOverride[b] == 0) Limits.CheckMass(total.Mass, "shape.Density (the body's mass from its shapes)");
            if (!float.IsFinite(total.Mass) || !Validate.IsFinite(total.Center) || !total.Inertia.IsFinite)
                throw new ArgumentException($"shape.Density: {Describe(b)}'s mass properties with this shape overflow (mass {total.Mass:G} kg); use a smaller shape or density.", "shape.Density");
        }

        /// <summary>Detaches and removes a shape; the body's mass is recomputed.</summary>
        public void RemoveShape(ShapeHandle shape)
        {
            ThrowIfInStep();
            int i = ShapeSlot(shape);
            int b = Shapes.Body[i];
            // Unlink from the body's list.
            if (Bodies.FirstShape[b] == i) Bodies.FirstShape[b] = Shapes.NextInBody[i];
            else
            {
                int p = Bodies.FirstShape[b];
                while (Shapes.NextInBody[p] != i) p = Shapes.NextInBody[p];
                Shapes.NextInBody[p] = Shapes.NextInBody[i];
            }
            ReleaseShape(i);
            UpdateMassProperties(b);
        }

        /// <summary>True when the handle names a live shape of this world.</summary>
        public bool IsValid(ShapeHandle shape) => shape.WorldId == Id && Shapes.IsLive(shape);

        /// <summary>The body a shape is attached to.</summary>
        public BodyHandle GetShapeBody(ShapeHandle shape)
        {
            int b = Shapes.Body[ShapeSlot(shape)];
            return new BodyHandle(b, Bodies.Generation[b], Id);
        }

        /// <summary>The geometry of a shape.</summary>
        public ShapeGeometry GetShapeGeometry(ShapeHandle shape) => Shapes.Geometry[ShapeSlot(shape)];

        /// <summary>The shape's pose in its body's frame.</summary>
        public Pose GetShapeLocalPose(ShapeHandle shape) => Shapes.LocalPose[ShapeSlot(shape)];

        /// <summary>The shape's world bounds as of the end of the last step (or its creation).</summary>
        public Aabb GetShapeAabb(ShapeHandle shape) => Shapes.WorldAabb[ShapeSlot(shape)];

        /// <summary>Copies the handles of a body's shapes into <paramref name="into"/>; returns how many there are in all.</summary>
        public int GetShapes(BodyHandle body, Span<ShapeHandle> into)
        {
            int n = 0;
            for (int s = Bodies.FirstShape[Slot(body)]; s >= 0; s = Shapes.NextInBody[s], n++)
                if (n < into.Length) into[n] = new ShapeHandle(s, Shapes.Generation[s], Id);
            return n;
        }

        internal int ShapeSlot(ShapeHandle shape) => LiveSlot(shape.Id, Shapes.Slots, nameof(ShapeHandle), "shape", "removed");

        /// <summary>The world pose of a shape: its body's pose times its local pose.</summary>
        internal Pose ShapeWorldPose(int shape) => Shapes.WorldPose(shape, Bodies);

        void ReleaseShape(int i)
        {
            OnShapeRemoved(i);
            Shapes.Release(i);
        }
    }
}
