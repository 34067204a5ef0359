using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// Resolved contact events and the manifold points they own (each contact's
    /// <see cref="BridgeContact.FirstPoint"/> indexes <see cref="Points"/>). The world side fills
    /// one per step; with a physics thread the steps' batches gather in an outbox that the game
    /// side swaps for its inbox and delivers. The arrays grow by doubling and are reused, so a
    /// steady stream of events allocates nothing.
    /// </summary>
    internal sealed class BridgeContactBatch
    {
        /// <summary>The contacts; the first <see cref="ContactCount"/> are in use.</summary>
        public BridgeContact[] Contacts = new BridgeContact[64];
        public int ContactCount;
        /// <summary>The contacts' points; the first <see cref="PointCount"/> are in use.</summary>
        public BridgeContactPoint[] Points = new BridgeContactPoint[64];
        public int PointCount;

        /// <summary>A new contact at the end, for the caller to fill.</summary>
        public ref BridgeContact AddContact()
        {
            if (ContactCount == Contacts.Length) Array.Resize(ref Contacts, Contacts.Length * 2);
            return ref Contacts[ContactCount++];
        }

        /// <summary>Appends a point (of the contact being filled).</summary>
        public void AddPoint(in BridgeContactPoint p)
        {
            if (PointCount == Points.Length) Array.Resize(ref Points, Points.Length * 2);
            Points[PointCount++] = p;
        }

        /// <summary>Appends the contacts and points of <paramref name="from"/>, its contacts' first points rebased into this batch's points.</summary>
        public void Append(BridgeContactBatch from)
        {
            if (ContactCount + from.ContactCount > Contacts.Length) Array.Resize(ref Contacts, Math.Max(Contacts.Length * 2, ContactCount + from.ContactCount));
            if (PointCount + from.PointCount > Points.Length) Array.Resize(ref Points, Math.Max(Points.Length * 2, PointCount + from.PointCount));
            for (int k = 0; k < from.ContactCount; k++)
            {
                Contacts[ContactCount + k] = from.Contacts[k];
                Contacts[ContactCount + k].FirstPoint += PointCount;
            }
            Array.Copy(from.Points, 0, Points, PointCount, from.PointCount);
            ContactCount += from.ContactCount;
            PointCount += from.PointCount;
        }

        /// <summary>Empties the batch, dropping the entity references its contacts held.</summary>
        public void Clear()
        {
            Array.Clear(Contacts, 0, ContactCount);
            ContactCount = 0;
            PointCount = 0;
        }
    }
}
