using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>The pool-or-caller choice of the soft colour loops, fed with fixed times.</summary>
    public class ThreadChoiceTests
    {
        // Runs passes whose time per element is fixed for each way; returns how many used the pool.
        static int PoolPasses(ThreadChoice choice, double pool, double caller, int passes)
        {
            int used = 0;
            for (int i = 0; i < passes; i++)
            {
                bool parallel = choice.Begin();
                if (parallel) used++;
                choice.Record(parallel ? pool : caller);
            }
            return used;
        }

        [Test]
        public void Tries_both_ways_first_then_keeps_the_faster_and_rechecks_the_other_once_in_64()
        {
            var choice = new ThreadChoice();
            Assert.That(choice.Begin(), Is.True, "first pass: the pool, not yet timed");
            choice.Record(2.0);
            Assert.That(choice.Begin(), Is.False, "second pass: the calling thread, not yet timed");
            choice.Record(1.0);
            // The pool twice as slow: the caller, except one pass in 64.
            Assert.That(PoolPasses(choice, 2.0, 1.0, 640), Is.EqualTo(10));
        }

        [Test]
        public void Follows_a_change_of_load_at_the_next_exploring_pass()
        {
            var choice = new ThreadChoice();
            PoolPasses(choice, 2.0, 1.0, 128);
            // The cores free up: the next exploring pass (at most 64 passes on) times the pool at
            // a third of the caller, and the passes after it use the pool.
            int used = PoolPasses(choice, 0.3, 1.0, 64 + 128);
            Assert.That(used, Is.GreaterThanOrEqualTo(126));
            // The load comes back: the pool is timed every pass, so a few passes bring the caller back.
            int after = PoolPasses(choice, 3.0, 1.0, 64);
            Assert.That(after, Is.LessThanOrEqualTo(5));
        }

        [Test]
        public void Prefers_the_calling_thread_unless_the_pool_is_clearly_faster()
        {
            var choice = new ThreadChoice();
            // 5 % faster on the pool is within the noise margin: the caller stays.
            Assert.That(PoolPasses(choice, 0.95, 1.0, 640), Is.LessThanOrEqualTo(11));
            var fast = new ThreadChoice();
            Assert.That(PoolPasses(fast, 0.5, 1.0, 640), Is.GreaterThanOrEqualTo(628));
        }
    }
}
