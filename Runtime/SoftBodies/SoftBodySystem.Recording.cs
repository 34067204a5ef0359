using System.Numerics;

namespace Fulcrum.SoftBodies
{
    // The soft-body blocks of a .frec recording (Documentation~/RecordingFormat.md): Core's
    // Recorder writes the rigid data and asks the world's soft-body stage for the rest.
    public sealed partial class SoftBodySystem : IRecordingStage
    {
        IRecordingBlock IRecordingStage.BeginRecording(World world) => new SoftBodyRecording(this, world);
    }

    /// <summary>
    /// One recording's soft bodies: those alive when it began, in the system's order, with
    /// per-element J and strain buffers reused every frame (a frame allocates nothing).
    /// </summary>
    internal sealed class SoftBodyRecording : IRecordingBlock
    {
        readonly World _world;
        readonly SoftBody[] _bodies;
        readonly float[][] _elementJ;
        readonly float[][] _elementStrain;
        readonly ElementStrain[] _strain;

        public SoftBodyRecording(SoftBodySystem system, World world)
        {
            _world = world;
            _bodies = new SoftBody[system.Count];
            _elementJ = new float[_bodies.Length][];
            _elementStrain = new float[_bodies.Length][];
            _strain = new ElementStrain[_bodies.Length];
            for (int k = 0; k < _bodies.Length; k++)
            {
                _bodies[k] = system[k];
                _elementJ[k] = new float[_bodies[k].ElementCount];
                _elementStrain[k] = new float[_bodies[k].ElementCount];
                _strain[k] = new ElementStrain(_bodies[k].Mesh);
            }
        }

        public void WriteHeader(RecordingWriter o)
        {
            o.U32(_bodies.Length);
            for (int k = 0; k < _bodies.Length; k++)
            {
                SoftBody sb = _bodies[k];
                SoftMesh mesh = sb.Mesh;
                o.Str(sb.Name ?? "soft" + k);
                o.U32(sb.VertexCount);
                System.ReadOnlySpan<int> elements = mesh.IsShell ? mesh.Triangles : mesh.Tetrahedra;
                o.U8(mesh.IsShell ? RecordingFormat.Triangles : RecordingFormat.Tetrahedra);
                o.U32(sb.ElementCount);
                foreach (int e in elements) o.U32(e);
                // The surface to draw: a shell is its own surface.
                System.ReadOnlySpan<int> surface = mesh.IsShell ? mesh.Triangles : mesh.SurfaceTriangles;
                o.U32(surface.Length / 3);
                foreach (int v in surface) o.U32(v);
            }
        }

        // Strain, kinetic and gravitational potential (from the origin, as the rigid potential
        // is), so that a settling soft body does not look like a gain.
        public float Energy()
        {
            float energy = 0;
            foreach (SoftBody sb in _bodies)
                if (!sb.IsDestroyed)
                {
                    SoftBodyStats stats = sb.ComputeStats();
                    energy += stats.StrainEnergy + stats.KineticEnergy - sb.TotalMass * sb.GravityScale * Vector3.Dot(_world.Gravity, stats.Centroid);
                }
            return energy;
        }

        public void WriteFrame(RecordingWriter o)
        {
            for (int k = 0; k < _bodies.Length; k++)
            {
                SoftBody sb = _bodies[k];
                foreach (Vector3 x in sb.Positions) o.V3(x);
                float[] jOfElement = _elementJ[k], strain = _elementStrain[k];
                if (!sb.IsDestroyed)
                {
                    sb.ComputeElementJ(jOfElement);
                    _strain[k].Compute(sb.Positions, strain);
                }
                foreach (float value in jOfElement) o.F32(value);
                foreach (float value in strain) o.F32(value);
            }
        }
    }
}
