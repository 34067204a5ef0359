namespace Fulcrum
{
    public sealed partial class World
    {
        // Shapes on bodies with continuous collision; the stage returns at once while it is 0.
        int _ccdShapeCount;

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

        void SolveContinuous(float dt)
        {
            if (_ccdShapeCount == 0) return;
        }
    }
}
