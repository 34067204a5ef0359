using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// A set of layers as a bit mask (Unity's LayerMask), convertible to and from the
    /// <c>int layerMask</c> the queries take. Layer names come from a table shared by the
    /// process, filled with Unity's built-in names (0 Default, 1 TransparentFX, 2 Ignore Raycast,
    /// 4 Water, 5 UI); name the others with <see cref="SetLayerName"/> (Unity reads them from
    /// the project's Tags and Layers settings, which a headless program does not have).
    /// </summary>
    public struct LayerMask
    {
        static readonly string[] s_names = CreateNames();

        /// <summary>The mask: bit (1 &lt;&lt; layer) is set for each layer in the set.</summary>
        public int value;

        /// <summary>The mask as an int.</summary>
        public static implicit operator int(LayerMask mask) => mask.value;

        /// <summary>A mask from an int.</summary>
        public static implicit operator LayerMask(int mask) => new LayerMask { value = mask };

        /// <summary>The mask of the named layers; unknown names are skipped (as in Unity).</summary>
        public static int GetMask(params string[] layerNames)
        {
            if (layerNames == null) throw new ArgumentNullException(nameof(layerNames));
            int mask = 0;
            foreach (string n in layerNames)
            {
                int layer = NameToLayer(n);
                if (layer >= 0) mask |= 1 << layer;
            }
            return mask;
        }

        /// <summary>The layer with this name, or -1.</summary>
        public static int NameToLayer(string layerName)
        {
            if (layerName == null) return -1;
            lock (s_names)
                for (int i = 0; i < 32; i++)
                    if (s_names[i].Length > 0 && s_names[i] == layerName) return i;
            return -1;
        }

        /// <summary>The name of a layer ("" when unnamed).</summary>
        public static string LayerToName(int layer)
        {
            if ((uint)layer >= 32u) return "";
            lock (s_names) return s_names[layer];
        }

        /// <summary>Names a layer (0-31) for <see cref="GetMask"/> and <see cref="NameToLayer"/>; a Fulcrum addition standing in for Unity's project settings.</summary>
        public static void SetLayerName(int layer, string name)
        {
            if ((uint)layer >= 32u) throw new ArgumentOutOfRangeException(nameof(layer), layer, "A layer is 0-31.");
            if (name == null) throw new ArgumentNullException(nameof(name));
            lock (s_names) s_names[layer] = name;
        }

        static string[] CreateNames()
        {
            var names = new string[32];
            for (int i = 0; i < 32; i++) names[i] = "";
            names[0] = "Default";
            names[1] = "TransparentFX";
            names[2] = "Ignore Raycast";
            names[4] = "Water";
            names[5] = "UI";
            return names;
        }
    }
}
