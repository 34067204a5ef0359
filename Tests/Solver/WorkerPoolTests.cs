using System.Threading;
using Fulcrum.Dynamics;
using NUnit.Framework;

namespace Fulcrum.Tests.Solver
{
    public class WorkerPoolTests
    {
        sealed class CountingJob : IParallelJob
        {
            public int[] Hits = new int[0];
            public void Execute(int start, int end)
            {
                for (int i = start; i < end; i++) Interlocked.Increment(ref Hits[i]);
            }
        }

        [Test]
        public void Every_item_of_every_call_runs_exactly_once_across_back_to_back_calls()
        {
            // Back-to-back calls with changing sizes are where a worker still finishing one call
            // could take a chunk of the next (the colour batches of a solve look like this).
            var pool = new WorkerPool(3);
            try
            {
                var jobs = new[] { new CountingJob(), new CountingJob() };
                for (int call = 0; call < 100000; call++)
                {
                    CountingJob job = jobs[call & 1];
                    int count = 8 + (call * 7919) % 120;
                    if (job.Hits.Length != count) job.Hits = new int[count];
                    else System.Array.Clear(job.Hits, 0, count);
                    pool.For(job, 0, count, 1);
                    for (int i = 0; i < count; i++)
                        if (job.Hits[i] != 1) Assert.Fail($"call {call}: item {i} of {count} ran {job.Hits[i]} times");
                }
                Assert.That(pool.SplitCalls, Is.GreaterThan(50000));
            }
            finally
            {
                pool.Stop();
            }
        }
    }
}
