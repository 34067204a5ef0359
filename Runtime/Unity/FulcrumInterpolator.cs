#nullable enable
using UnityEngine;

namespace Fulcrum.Unity
{
    /// <summary>Runs first in Update and shows the interpolated body poses of its <see cref="FulcrumWorld"/>.</summary>
    [DefaultExecutionOrder(-10000)]
    [RequireComponent(typeof(FulcrumWorld))]
    public sealed class FulcrumInterpolator : MonoBehaviour
    {
        FulcrumWorld? _world;

        void Awake() => _world = GetComponent<FulcrumWorld>();

        void Update() => _world!.Interpolate();
    }
}
