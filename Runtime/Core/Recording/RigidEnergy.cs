using System.Numerics;

namespace Fulcrum
{
    /// <summary>
    /// Mechanical energy of a world's dynamic bodies: kinetic 1/2 m v^2 + 1/2 w . L, and
    /// potential -m g . c measured from the world origin (c the centre of mass). Their sum is
    /// conserved by a free fall up to the integrator's error, so its change ("drift") is a
    /// health check on the solver. Used by the recorder and by the runner's traces.
    /// </summary>
    internal static class RigidEnergy
    {
        public static float Kinetic(World world)
        {
            BodyStorage b = world.Bodies;
            float e = 0;
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                if (b.Type[i] != BodyType.Dynamic) continue;
                e += world.GetBody(new BodyHandle(i, b.Generation[i], world.Id)).KineticEnergy;
            }
            return e;
        }

        public static float Potential(World world)
        {
            BodyStorage b = world.Bodies;
            Vector3 g = world.Gravity;
            float e = 0;
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                if (b.Type[i] != BodyType.Dynamic) continue;
                e -= b.Mass[i] * b.GravityScale[i] * Vector3.Dot(g, b.Center[i]);
            }
            return e;
        }
    }
}
