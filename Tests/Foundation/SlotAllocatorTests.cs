using System;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>
    /// The one slot allocator behind every handle type (bodies, shapes, joints, soft bodies,
    /// bridge proxies): the order it reuses slots in and keeps live slots in is part of every
    /// run's determinism, so it is pinned here.
    /// </summary>
    public class SlotAllocatorTests
    {
        static int Take(SlotAllocator s) => s.Allocate(out _);

        static int[] Live(SlotAllocator s) => s.Active.AsSpan(0, s.ActiveCount).ToArray();

        [Test]
        public void Freed_slots_are_reused_last_freed_first_and_a_removal_swaps_the_last_live_slot_in()
        {
            var s = new SlotAllocator();
            for (int i = 0; i < 4; i++) Assert.That(Take(s), Is.EqualTo(i));
            s.Release(1);
            s.Release(0);
            Assert.That(Live(s), Is.EqualTo(new[] { 2, 3 }), "0 and 1 each replaced by the last live slot");
            Assert.That(Take(s), Is.EqualTo(0), "last freed first");
            Assert.That(Take(s), Is.EqualTo(1));
            Assert.That(Take(s), Is.EqualTo(4), "then new slots");
            Assert.That(Live(s), Is.EqualTo(new[] { 2, 3, 0, 1, 4 }));
        }

        [Test]
        public void A_slot_changes_generation_when_taken_and_when_freed()
        {
            var s = new SlotAllocator();
            int slot = Take(s);
            Assert.That(s.IsLive(slot, 1), Is.True);
            s.Release(slot);
            Assert.That(s.IsLive(slot, 1), Is.False);
            Assert.That(Take(s), Is.EqualTo(slot));
            Assert.That(s.Generation[slot], Is.EqualTo(3));
            Assert.That(s.IsLive(slot, 1), Is.False, "the handle from before the reuse");
            Assert.That(s.IsLive(slot, 3), Is.True);
            Assert.That(s.IsLive(slot, 0), Is.False, "none");
        }

        [Test]
        public void PeekNext_names_the_slot_and_generation_that_Allocate_then_takes_without_taking_it()
        {
            var s = new SlotAllocator();
            void Check(string when)
            {
                int peeked = s.PeekNext(out int generation);
                int live = s.ActiveCount;
                Assert.That(s.PeekNext(out int again), Is.EqualTo(peeked), when + ": peeking changes nothing");
                Assert.That(again, Is.EqualTo(generation));
                Assert.That(s.ActiveCount, Is.EqualTo(live));
                int slot = Take(s);
                Assert.That(slot, Is.EqualTo(peeked), when);
                Assert.That(s.Generation[slot], Is.EqualTo(generation), when);
            }
            Check("empty");
            for (int i = 1; i < 16; i++) Take(s);
            Check("at the capacity, before it grows");
            s.Release(3);
            s.Release(7);
            Check("a freed slot");
            Check("the slot freed before it");
        }

        [Test]
        public void SetActiveOrder_puts_the_live_slots_in_the_given_order()
        {
            var s = new SlotAllocator();
            for (int i = 0; i < 3; i++) Take(s);
            s.SetActiveOrder(new[] { 2, 0, 1 });
            Assert.That(Live(s), Is.EqualTo(new[] { 2, 0, 1 }));
            Assert.That(s.ActiveIndex.AsSpan(0, 3).ToArray(), Is.EqualTo(new[] { 1, 2, 0 }));
            s.Release(2);
            Assert.That(Live(s), Is.EqualTo(new[] { 1, 0 }), "a removal still swaps the last one in");
            Assert.That(() => s.SetActiveOrder(new[] { 0 }), Throws.ArgumentException);
        }
    }
}
