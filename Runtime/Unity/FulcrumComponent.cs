#nullable enable
using UnityEngine;

namespace Fulcrum.Unity
{
    /// <summary>The base of the Fulcrum MonoBehaviours: finds the <see cref="FulcrumWorld"/> and the GameObject's shadow entity.</summary>
    public abstract class FulcrumComponent : MonoBehaviour
    {
        /// <summary>The shadow entity of this GameObject in the headless scene.</summary>
        protected Fulcrum.Components.Entity Shadow => FulcrumWorld.Instance.EntityFor(gameObject);

        /// <summary>Removes the shadow entity when this was the GameObject's last Fulcrum component.</summary>
        protected void ReleaseShadow()
        {
            FulcrumWorld? w = FulcrumWorld.Current;
            if (w != null) w.Release(gameObject, this);
        }

        /// <summary>True while play mode runs and the component is live: inspector edits (OnValidate) are then pushed to the headless component.</summary>
        protected bool IsLive => Application.isPlaying && isActiveAndEnabled;
    }
}
