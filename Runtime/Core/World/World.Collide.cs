namespace Fulcrum
{
    public sealed partial class World
    {
        // Collision stages. Until the broad and narrow phases exist these keep the shapes'
        // world bounds current and find no contacts.

        void OnShapeAdded(int shape) { }

        void OnShapeRemoved(int shape) { }

        void UpdateBroadPhase()
        {
            ShapeStorage s = Shapes;
            for (int k = 0; k < s.ActiveCount; k++)
            {
                int i = s.Active[k];
                int b = s.Body[i];
                if (Bodies.Type[b] == BodyType.Static || !Bodies.Awake[b]) continue;
                s.WorldAabb[i] = s.Geometry[i].ComputeAabb(ShapeWorldPose(i));
            }
        }

        void UpdateContacts() { }

        void SolveContinuous(float dt) { }

        void PublishEvents() { }
    }
}
