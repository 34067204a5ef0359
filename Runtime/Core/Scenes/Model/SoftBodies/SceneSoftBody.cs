using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// An entry of <c>softBodies</c>: a Neo-Hookean solid meshed from <see cref="Mesh"/>. Kept
    /// as data by Core; Fulcrum.SoftBodies turns it into a soft body.
    /// </summary>
    public sealed class SceneSoftBody
    {
        /// <summary><c>name</c>: unique among soft bodies. Required.</summary>
        public string Name { get; set; } = "";

        /// <summary><c>mesh</c>: the rest shape. Required.</summary>
        public SceneSoftMesh? Mesh { get; set; }

        /// <summary><c>material</c>: the constitutive model and its constants. Required.</summary>
        public SceneSoftMaterial? Material { get; set; }

        /// <summary><c>position</c>: world position of the mesh centre, m. Default: 0.</summary>
        public Vector3 Position { get; set; }

        /// <summary><c>pinned</c>: rest-space boxes whose vertices are fixed or attached to a body. Default: none.</summary>
        public List<ScenePin> Pinned { get; } = new List<ScenePin>();

        /// <summary>
        /// <c>initialDeformation</c>: maps rest positions (about the mesh centre) to starting
        /// positions; written as three rows <c>[[a,b,c],[d,e,f],[g,h,i]]</c>. Non-singular; a
        /// negative determinant starts the body inverted. Default: identity.
        /// </summary>
        public Mat3 InitialDeformation { get; set; } = Mat3.Identity;

        /// <summary><c>probes</c>: material points in rest coordinates (about the mesh centre) reported in traces, m. Default: none.</summary>
        public List<Vector3> Probes { get; } = new List<Vector3>();

        /// <summary><c>plasticity</c> (an extension of fulcrum-scene/1). Default: null, elastic.</summary>
        public ScenePlasticity? Plasticity { get; set; }
    }
}
