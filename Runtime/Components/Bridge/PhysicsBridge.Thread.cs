using System;
using System.Diagnostics;
using System.Numerics;
using System.Threading;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    // The optional physics thread: it owns the world, steps it at its own rate, and publishes
    // poses (triple-rotated buffers: the game reads the last two while the thread fills a third)
    // and events (an outbox swapped under the lock) for the game thread.
    public sealed partial class PhysicsBridge
    {
        Thread? _thread;
        volatile bool _stop;
        Exception? _threadError;
        BridgeCommandQueue _applying = new BridgeCommandQueue();

        // Shared under _sync.
        Pose[] _snapPrev = new Pose[16], _snapCur = new Pose[16], _snapBack = new Pose[16];
        int[] _snapPrevGen = new int[16], _snapCurGen = new int[16], _snapBackGen = new int[16];
        long _publishTicks;
        long _stepsPublished;
        BridgeContactBatch _outbox = new BridgeContactBatch();
        Pose[] _sharedInput = new Pose[16];
        bool[] _sharedInputSet = new bool[16];

        // Game thread only.
        long _stepsDelivered;
        BridgeContactBatch _inbox = new BridgeContactBatch(); // empty between deliveries
        Pose[] _gPrev = new Pose[16], _gCur = new Pose[16];
        int[] _gPrevGen = new int[16], _gCurGen = new int[16];

        /// <summary>Steps the physics thread has taken (0 without one).</summary>
        public long ThreadSteps => Interlocked.Read(ref _stepsPublished);

        void StartThread()
        {
            _thread = new Thread(RunThread) { IsBackground = true, Name = "Fulcrum physics" };
            _thread.Start();
        }

        void StopThread()
        {
            if (_thread == null) return;
            _stop = true;
            _thread.Join();
            _thread = null;
        }

        void ThrowIfThreadFailed()
        {
            Exception? e = Volatile.Read(ref _threadError);
            if (e != null) throw new InvalidOperationException($"The physics thread stopped: {e.Message}", e);
        }

        void RunThread()
        {
            long period = (long)(Stopwatch.Frequency / _settings.ThreadRateHz);
            long next = Stopwatch.GetTimestamp() + period;
            try
            {
                while (!_stop)
                {
                    long now = Stopwatch.GetTimestamp();
                    if (now < next)
                    {
                        // Sleep when far from the tick (Sleep(1) may last a few ms), yield when close.
                        if (next - now > Stopwatch.Frequency / 250) Thread.Sleep(1);
                        else Thread.Yield();
                        continue;
                    }
                    // More than a few steps behind (a stall): drop the time instead of catching up.
                    next = now - next > 4 * period ? now + period : next + period;
                    PhysicsTick();
                }
            }
            catch (Exception e)
            {
                Volatile.Write(ref _threadError, e);
            }
        }

        void PhysicsTick()
        {
            lock (_sync)
            {
                BridgeCommandQueue incoming = _commands;
                _commands = _applying;
                _applying = incoming;
                TakeSharedInputs();
            }
            ApplyCommands(_applying);
            TakeRecordStart();
            StepWorld(_stepper.FixedDt, 0, 1);
            WriteSnapshot();
            lock (_sync)
            {
                Swap(ref _snapPrev, ref _snapCur);
                Swap(ref _snapCur, ref _snapBack);     // cur <- new poses, back <- the oldest (reused next step)
                Swap(ref _snapPrevGen, ref _snapCurGen);
                Swap(ref _snapCurGen, ref _snapBackGen);
                _publishTicks = Stopwatch.GetTimestamp();
                _outbox.Append(_wEvents);
                Interlocked.Increment(ref _stepsPublished);
            }
            _wEvents.Clear();
            TakeRecordStop();
        }

        static void Swap<T>(ref T a, ref T b)
        {
            T t = a;
            a = b;
            b = t;
        }

        // Physics thread, under _sync: the latest game poses become this step's targets.
        void TakeSharedInputs()
        {
            int n = Math.Min(_sharedInputSet.Length, _wSlotCount);
            for (int slot = 0; slot < n; slot++)
            {
                if (!_sharedInputSet[slot]) continue;
                _sharedInputSet[slot] = false;
                if (_wBody[slot].IsNone || _wMode[slot] != DriveMode.Game) continue;
                SetTarget(slot, _sharedInput[slot]);
            }
        }

        // Physics thread: poses of this step into the back buffer, stamped with the slot generation.
        void WriteSnapshot()
        {
            if (_snapBack.Length < _wSlotCount)
            {
                lock (_sync)
                {
                    int n = Math.Max(_wSlotCount, _snapBack.Length * 2);
                    Array.Resize(ref _snapPrev, n);
                    Array.Resize(ref _snapCur, n);
                    Array.Resize(ref _snapBack, n);
                    Array.Resize(ref _snapPrevGen, n);
                    Array.Resize(ref _snapCurGen, n);
                    Array.Resize(ref _snapBackGen, n);
                }
            }
            for (int slot = 0; slot < _wSlotCount; slot++)
            {
                if (_wBody[slot].IsNone) { _snapBackGen[slot] = 0; continue; }
                _snapBack[slot] = _world.GetBody(_wBody[slot]).Pose;
                _snapBackGen[slot] = _wGeneration[slot];
            }
        }

        // Game thread: hand the game-driven poses to the physics thread.
        void PostInputs()
        {
            lock (_sync)
            {
                if (_sharedInput.Length < _gSlots.SlotCount)
                {
                    Array.Resize(ref _sharedInput, _gInput.Length);
                    Array.Resize(ref _sharedInputSet, _gInput.Length);
                }
                for (int slot = 0; slot < _gSlots.SlotCount; slot++)
                {
                    if (_gState[slot] != Live || _gMode[slot] != DriveMode.Game || _gStatic[slot]) continue;
                    _sharedInput[slot] = _gInput[slot];
                    _sharedInputSet[slot] = true;
                }
            }
        }

        // Game thread: delivers the events the thread published since the last call.
        int DeliverThreadEvents()
        {
            long steps;
            lock (_sync)
            {
                Swap(ref _outbox, ref _inbox); // the thread goes on with the emptied inbox
                steps = _stepsPublished - _stepsDelivered;
                _stepsDelivered = _stepsPublished;
            }
            Deliver(_inbox);
            _inbox.Clear();
            return (int)steps;
        }

        // Game thread: copy the last two published poses, then blend by the wall time since the
        // newer one was published (one step behind real time, never extrapolated).
        void WriteThreadPoses()
        {
            long published;
            lock (_sync)
            {
                int n = _snapCur.Length;
                if (_gCur.Length < n)
                {
                    Array.Resize(ref _gPrev, n);
                    Array.Resize(ref _gCur, n);
                    Array.Resize(ref _gPrevGen, n);
                    Array.Resize(ref _gCurGen, n);
                }
                Array.Copy(_snapPrev, _gPrev, n);
                Array.Copy(_snapCur, _gCur, n);
                Array.Copy(_snapPrevGen, _gPrevGen, n);
                Array.Copy(_snapCurGen, _gCurGen, n);
                published = _publishTicks;
            }
            float alpha = 1f;
            if (_settings.Interpolate)
            {
                double period = Stopwatch.Frequency / (double)_settings.ThreadRateHz;
                alpha = (float)Math.Min(1.0, Math.Max(0.0, (Stopwatch.GetTimestamp() - published) / period));
            }
            int count = Math.Min(_gSlots.SlotCount, _gCur.Length);
            for (int slot = 0; slot < count; slot++)
            {
                if (_gState[slot] != Live || _gMode[slot] != DriveMode.Physics || _gCurGen[slot] != _gSlots.Generation[slot]) continue;
                Pose cur = _gCur[slot];
                if (_gPrevGen[slot] == _gSlots.Generation[slot])
                {
                    Pose prev = _gPrev[slot];
                    cur = new Pose(Vector3.Lerp(prev.Position, cur.Position, alpha), Quaternion.Slerp(prev.Rotation, cur.Rotation, alpha));
                }
                _gEntity[slot]!.SetPose(cur.Position, cur.Rotation);
            }
        }
    }
}
