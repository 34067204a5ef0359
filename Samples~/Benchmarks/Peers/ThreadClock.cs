using System;
using System.Diagnostics;
using System.Runtime.InteropServices;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// CPU time of the calling thread, in ms, where the OS gives it with sub-microsecond resolution
    /// (64-bit Linux: clock_gettime(CLOCK_THREAD_CPUTIME_ID)); elsewhere wall time. On a machine
    /// shared with other work, a step's wall time includes every time slice taken by another
    /// process; its thread CPU time does not, so engines measured minutes apart stay comparable.
    /// </summary>
    public static class ThreadClock
    {
        const int ClockProcessCpuTimeId = 2;
        const int ClockThreadCpuTimeId = 3;

        [StructLayout(LayoutKind.Sequential)]
        struct TimeSpec
        {
            public long Seconds;
            public long Nanoseconds;
        }

        [DllImport("libc", EntryPoint = "clock_gettime")]
        static extern int ClockGetTime(int clock, out TimeSpec time);

        /// <summary>Whether <see cref="NowMs"/> is thread CPU time (true) or wall time.</summary>
        public static readonly bool IsCpuTime = Probe();

        static bool Probe()
        {
            if (!OperatingSystem.IsLinux() || !Environment.Is64BitProcess) return false;
            try { return ClockGetTime(ClockThreadCpuTimeId, out _) == 0; }
            catch (DllNotFoundException) { return false; }
            catch (EntryPointNotFoundException) { return false; }
        }

        /// <summary>
        /// CPU time of the whole process (every thread: workers, and the runtime's own), ms, where
        /// <see cref="IsCpuTime"/>; otherwise NaN. Only differences mean anything.
        /// </summary>
        public static double ProcessNowMs()
        {
            if (IsCpuTime && ClockGetTime(ClockProcessCpuTimeId, out TimeSpec t) == 0)
                return t.Seconds * 1e3 + t.Nanoseconds * 1e-6;
            return double.NaN;
        }

        /// <summary>The clock's reading, ms; only differences mean anything.</summary>
        public static double NowMs()
        {
            if (IsCpuTime && ClockGetTime(ClockThreadCpuTimeId, out TimeSpec t) == 0)
                return t.Seconds * 1e3 + t.Nanoseconds * 1e-6;
            return Stopwatch.GetTimestamp() * 1e3 / Stopwatch.Frequency;
        }
    }
}
