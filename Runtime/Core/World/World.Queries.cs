using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        // Set after each step: the step moved bodies after the broad phase sized their fat
        // boxes, so a query first brings the moving shapes' bounds up to date.
        bool _queryBoundsStale;

        // Recomputes the tight bounds of moving shapes at their current poses and moves
        // the proxies that left their fat boxes (they join the next step's pair search).
        internal void RefreshQueryBounds()
        {
            if (!_queryBoundsStale) return;
            _queryBoundsStale = false;
            ShapeStorage s = Shapes;
            for (int k = 0; k < s.ActiveCount; k++)
            {
                int i = s.Active[k];
                int body = s.Body[i];
                // Bodies that fell asleep in the step moved in it too: only static ones are skipped.
                if (Bodies.Type[body] == BodyType.Static) continue;
                Aabb tight = s.Geometry[i].ComputeAabb(ShapeWorldPose(i));
                s.WorldAabb[i] = tight;
                if (!BroadPhase.FatAabb(s.ProxyId[i]).Contains(tight))
                    BroadPhase.MoveProxy(s.ProxyId[i], tight.Expanded(Collision.CollisionMargins.AabbMargin));
            }
        }
    }
}
