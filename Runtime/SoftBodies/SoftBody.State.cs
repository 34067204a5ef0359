using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    public sealed partial class SoftBody
    {
        /// <summary>
        /// Writes what a step reads and may change: positions (current, previous, step start),
        /// velocities, masses and pins, the elements' rest state (plastic flow rewrites it), the
        /// multipliers, the attachments and the settings a user can change. The mesh and
        /// material are not written: the body a state is restored into was built from them.
        /// </summary>
        internal void WriteState(StateWriter w)
        {
            w.Write(X.Length);
            w.Write(Tets.Length);
            w.Write(Tris.Length);
            w.Write(Bends.Length);
            w.Write(Attachments.Length);
            w.WriteArray(X);
            w.WriteArray(XPrev);
            w.WriteArray(XStart);
            w.WriteArray(V);
            w.WriteArray(W);
            w.WriteArray(M);
            w.WriteArray(FreeW);
            w.WriteArray(Tets);
            w.WriteArray(TetLambda);
            TetData.ExportGradients(TetGrad);
            w.WriteArray(TetGrad);
            w.WriteArray(PlasticStrain);
            w.WriteArray(Tris);
            w.WriteArray(TriLambda);
            w.WriteArray(Bends);
            w.WriteArray(BendLambda);
            w.WriteArray(Attachments);
            w.Write(Substeps);
            w.Write(Iterations);
            w.Write(DampingTime);
            w.Write(LinearDamping);
            w.Write(GravityScale);
            w.Write(Friction);
            w.Write(CollideWithShapes);
            w.Write(CollideWithSoftBodies);
            w.Write(Plasticity);
            w.Write(Solver);
            Contacts.WriteState(w);
        }

        /// <summary>
        /// Reads what <see cref="WriteState"/> wrote, checks that it fits this body (same vertex,
        /// element and attachment counts) and returns what copies it in; changes nothing itself.
        /// </summary>
        internal Action PrepareRestore(StateReader r)
        {
            string who = Name != null ? $"soft body '{Name}' ({Handle})" : $"soft body {Handle}";
            int vertices = r.Read<int>("soft vertex count"), tets = r.Read<int>("soft tet count"), tris = r.Read<int>("soft triangle count");
            int bends = r.Read<int>("soft bend count"), attachments = r.Read<int>("soft attachment count");
            if (vertices != X.Length || tets != Tets.Length || tris != Tris.Length || bends != Bends.Length || attachments != Attachments.Length)
                throw r.Error($"{who} has {X.Length} vertices, {Tets.Length} tets, {Tris.Length} triangles, {Bends.Length} bend pairs and {Attachments.Length} attachments; "
                    + $"the state has {vertices}, {tets}, {tris}, {bends} and {attachments}: build the same soft bodies before restoring.");
            Vector3[] x = r.ReadArrayExactly<Vector3>("soft positions", X.Length);
            Vector3[] xPrev = r.ReadArrayExactly<Vector3>("soft previous positions", X.Length);
            Vector3[] xStart = r.ReadArrayExactly<Vector3>("soft step-start positions", X.Length);
            Vector3[] v = r.ReadArrayExactly<Vector3>("soft velocities", X.Length);
            float[] w = r.ReadArrayExactly<float>("soft inverse masses", X.Length);
            float[] m = r.ReadArrayExactly<float>("soft masses", X.Length);
            float[] freeW = r.ReadArrayExactly<float>("soft free inverse masses", X.Length);
            TetElement[] tetElements = r.ReadArrayExactly<TetElement>("soft tets", Tets.Length);
            Vector2[] tetLambda = r.ReadArrayExactly<Vector2>("soft tet multipliers", TetLambda.Length);
            TetGradients[] tetGrad = r.ReadArrayExactly<TetGradients>("soft tet gradients", TetGrad.Length);
            float[] plastic = r.ReadArrayExactly<float>("soft plastic strain", PlasticStrain.Length);
            TriangleElement[] triElements = r.ReadArrayExactly<TriangleElement>("soft triangles", Tris.Length);
            Vector2[] triLambda = r.ReadArrayExactly<Vector2>("soft triangle multipliers", TriLambda.Length);
            BendElement[] bendElements = r.ReadArrayExactly<BendElement>("soft bend pairs", Bends.Length);
            float[] bendLambda = r.ReadArrayExactly<float>("soft bend multipliers", BendLambda.Length);
            Attachment[] attached = r.ReadArrayExactly<Attachment>("soft attachments", Attachments.Length);
            int substeps = r.Read<int>("soft substeps"), iterations = r.Read<int>("soft iterations");
            float dampingTime = r.Read<float>("soft damping time"), linearDamping = r.Read<float>("soft linear damping");
            float gravityScale = r.Read<float>("soft gravity scale"), friction = r.Read<float>("soft friction");
            bool withShapes = r.Read<bool>("soft shape collision flag"), withSoft = r.Read<bool>("soft soft-collision flag");
            var plasticity = r.Read<SoftPlasticity>("soft plasticity");
            var solver = r.Read<SoftSolver>("soft solver");
            Action contacts = Contacts.PrepareRestore(r, X.Length);
            if (solver != SoftSolver.Xpbd && (solver != SoftSolver.Newton || Tets.Length == 0)) throw r.Error($"{who}: saved solver {(int)solver} does not fit this body.");
            for (int i = 0; i < tetElements.Length; i++)
            {
                ref TetElement t = ref tetElements[i];
                if ((uint)t.A >= (uint)vertices || (uint)t.B >= (uint)vertices || (uint)t.C >= (uint)vertices || (uint)t.D >= (uint)vertices)
                    throw r.Error($"{who}: saved tet {i} uses a vertex outside the body.");
            }
            for (int i = 0; i < triElements.Length; i++)
                if ((uint)triElements[i].A >= (uint)vertices || (uint)triElements[i].B >= (uint)vertices || (uint)triElements[i].C >= (uint)vertices)
                    throw r.Error($"{who}: saved triangle {i} uses a vertex outside the body.");
            for (int i = 0; i < bendElements.Length; i++)
            {
                ref BendElement b = ref bendElements[i];
                if ((uint)b.A >= (uint)vertices || (uint)b.B >= (uint)vertices || (uint)b.C >= (uint)vertices || (uint)b.D >= (uint)vertices)
                    throw r.Error($"{who}: saved bend pair {i} uses a vertex outside the body.");
            }
            for (int i = 0; i < attached.Length; i++)
                if ((uint)attached[i].Vertex >= (uint)vertices) throw r.Error($"{who}: saved attachment {i} uses vertex {attached[i].Vertex}.");
            if (iterations < 1 || substeps < 0) throw r.Error($"{who}: saved iterations {iterations} or substeps {substeps} are invalid.");
            return () =>
            {
                x.CopyTo(X, 0);
                xPrev.CopyTo(XPrev, 0);
                PositionsChanged();
                xStart.CopyTo(XStart, 0);
                v.CopyTo(V, 0);
                w.CopyTo(W, 0);
                m.CopyTo(M, 0);
                freeW.CopyTo(FreeW, 0);
                tetElements.CopyTo(Tets, 0);
                tetLambda.CopyTo(TetLambda, 0);
                tetGrad.CopyTo(TetGrad, 0);
                TetData.LoadElements(Tets);
                TetData.ImportGradients(TetGrad);
                plastic.CopyTo(PlasticStrain, 0);
                triElements.CopyTo(Tris, 0);
                triLambda.CopyTo(TriLambda, 0);
                bendElements.CopyTo(Bends, 0);
                bendLambda.CopyTo(BendLambda, 0);
                attached.CopyTo(Attachments, 0);
                Substeps = substeps;
                Iterations = iterations;
                DampingTime = dampingTime;
                LinearDamping = linearDamping;
                GravityScale = gravityScale;
                Friction = friction;
                CollideWithShapes = withShapes;
                CollideWithSoftBodies = withSoft;
                Plasticity = plasticity;
                Solver = solver;
                contacts();
            };
        }
    }
}
