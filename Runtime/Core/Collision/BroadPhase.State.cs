namespace Fulcrum.Collision
{
    internal sealed partial class BroadPhase
    {
        /// <summary>Writes both trees and the proxies waiting for a pair search.</summary>
        public void Save(StateWriter w)
        {
            w.Section("BROA");
            StaticTree.Save(w);
            MovingTree.Save(w);
            w.WritePool(_moved, _movedCount);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new broad phase.</summary>
        public static BroadPhase Load(StateReader r)
        {
            r.Section("BROA");
            var b = new BroadPhase();
            b.StaticTree.Load(r, "static tree");
            b.MovingTree.Load(r, "moving tree");
            b._moved = r.ReadPool<int>("moved proxies", out b._movedCount);
            return b;
        }
    }
}
