using System;

namespace ComponentsSample
{
    /// <summary>A crate lands on the ground and a ball rolls through a trigger: the tight (component) integration, headless.</summary>
    public static class Program
    {
        public static int Main()
        {
            ComponentsScene sample = ComponentsScene.Create(fixedDeltaTime: 1f / 50f);

            // A 60 Hz render loop over a 50 Hz physics step for two simulated seconds.
            for (int frame = 0; frame < 120; frame++) sample.Scene.Tick(1f / 60f);

            var scene = sample.Scene;
            Console.WriteLine($"crate at y = {sample.Crate.transform.position.Y:F3} m after {scene.fixedTime:F2} s ({scene.world.StepIndex} steps, {scene.frameCount} frames)");
            Console.WriteLine($"ball at x = {sample.Ball.transform.position.X:F3} m");
            return 0;
        }
    }
}
