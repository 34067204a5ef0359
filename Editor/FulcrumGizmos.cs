#nullable enable
using Fulcrum.Unity;
using UnityEditor;
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Editor
{
    /// <summary>
    /// Scene-view gizmos for the Fulcrum colliders (wire shapes, cyan; triggers yellow) and, in
    /// play mode, the contact points of the last step (red) with their normals.
    /// </summary>
    public static class FulcrumGizmos
    {
        static readonly Color Solid = new Color(0.3f, 0.9f, 1f, 0.9f);
        static readonly Color Trigger = new Color(1f, 0.85f, 0.2f, 0.9f);

        [DrawGizmo(GizmoType.Selected | GizmoType.NonSelected)]
        static void DrawBox(FulcrumBoxCollider c, GizmoType type)
        {
            Gizmos.color = c.isTrigger ? Trigger : Solid;
            Gizmos.matrix = c.transform.localToWorldMatrix;
            Gizmos.DrawWireCube(c.center, c.size);
            Gizmos.matrix = Matrix4x4.identity;
        }

        [DrawGizmo(GizmoType.Selected | GizmoType.NonSelected)]
        static void DrawSphere(FulcrumSphereCollider c, GizmoType type)
        {
            Gizmos.color = c.isTrigger ? Trigger : Solid;
            Gizmos.matrix = c.transform.localToWorldMatrix;
            Gizmos.DrawWireSphere(c.center, c.radius);
            Gizmos.matrix = Matrix4x4.identity;
        }

        [DrawGizmo(GizmoType.Selected | GizmoType.NonSelected)]
        static void DrawCapsule(FulcrumCapsuleCollider c, GizmoType type)
        {
            Gizmos.color = c.isTrigger ? Trigger : Solid;
            Gizmos.matrix = c.transform.localToWorldMatrix;
            Vector3 axis = c.direction == 0 ? Vector3.right : c.direction == 2 ? Vector3.forward : Vector3.up;
            float half = Mathf.Max(0f, 0.5f * c.height - c.radius);
            Vector3 a = c.center + axis * half, b = c.center - axis * half;
            Gizmos.DrawWireSphere(a, c.radius);
            Gizmos.DrawWireSphere(b, c.radius);
            Vector3 side1 = Vector3.Cross(axis, axis == Vector3.up ? Vector3.right : Vector3.up).normalized * c.radius;
            Vector3 side2 = Vector3.Cross(axis, side1).normalized * c.radius;
            Gizmos.DrawLine(a + side1, b + side1);
            Gizmos.DrawLine(a - side1, b - side1);
            Gizmos.DrawLine(a + side2, b + side2);
            Gizmos.DrawLine(a - side2, b - side2);
            Gizmos.matrix = Matrix4x4.identity;
        }

        [DrawGizmo(GizmoType.Selected | GizmoType.NonSelected)]
        static void DrawContacts(FulcrumWorld w, GizmoType type)
        {
            if (!Application.isPlaying) return;
            World world = w.Scene.world;
            Gizmos.color = Color.red;
            foreach (Fulcrum.Collision.ContactEvent e in world.ContactEvents)
            {
                if (e.IsSensor || e.Kind == Fulcrum.Collision.ContactEventKind.End || e.PointCount == 0) continue;
                Vector3 p = e.Point.ToUnity();
                Gizmos.DrawSphere(p, 0.03f);
                Gizmos.DrawLine(p, p + e.Normal.ToUnity() * 0.3f);
            }
        }
    }
}
