// Test double: SubsystemManager lists the subsystem instances a driver registered; Start/Stop set running.
// Transcribed from Unity's C# reference source, branch 2022.3: Modules/Subsystems/ISubsystem.cs,
// ISubsystemDescriptor.cs, SubsystemManager.cs, SubsystemWithProvider.cs, SubsystemDescriptorWithProvider.cs,
// SubsystemProvider.cs (module com.unity.modules.subsystems). Only the public members the XR Hands declarations
// derive from or the package calls; the internal plumbing is left out.
using System.Collections.Generic;

namespace UnityEngine
{
    public interface ISubsystem
    {
        bool running { get; }
        void Start();
        void Stop();
        void Destroy();
    }

    public interface ISubsystemDescriptor
    {
        string id { get; }
        ISubsystem Create();
    }

    public static partial class SubsystemManager
    {
        internal static readonly List<ISubsystem> Instances = new List<ISubsystem>();

        public static void GetSubsystems<T>(List<T> subsystems) where T : ISubsystem
        {
            subsystems.Clear();
            foreach (ISubsystem s in Instances)
                if (s is T t) subsystems.Add(t);
        }
    }
}

namespace UnityEngine.SubsystemsImplementation
{
    public abstract class SubsystemWithProvider : ISubsystem
    {
        public void Start()
        {
            if (running) return;
            running = true;
            OnStart();
        }

        protected abstract void OnStart();

        public void Stop()
        {
            if (!running) return;
            running = false;
            OnStop();
        }

        protected abstract void OnStop();

        public void Destroy()
        {
            Stop();
            SubsystemManager.Instances.Remove(this);
            OnDestroy();
        }

        protected abstract void OnDestroy();
        public bool running { get; private set; }
    }

    public abstract class SubsystemWithProvider<TSubsystem, TSubsystemDescriptor, TProvider> : SubsystemWithProvider
        where TSubsystem : SubsystemWithProvider, new()
        where TSubsystemDescriptor : SubsystemDescriptorWithProvider
        where TProvider : SubsystemProvider<TSubsystem>
    {
        public TSubsystemDescriptor subsystemDescriptor { get; internal set; }
        protected override void OnStart() { }
        protected override void OnStop() { }
        protected override void OnDestroy() { }
    }

    public abstract class SubsystemDescriptorWithProvider : ISubsystemDescriptor
    {
        public string id { get; set; }
        ISubsystem ISubsystemDescriptor.Create() => CreateImpl();
        internal abstract ISubsystem CreateImpl();
    }

    public class SubsystemDescriptorWithProvider<TSubsystem, TProvider> : SubsystemDescriptorWithProvider
        where TSubsystem : SubsystemWithProvider, new()
        where TProvider : SubsystemProvider<TSubsystem>
    {
        public TSubsystem Create()
        {
            var s = new TSubsystem();
            SubsystemManager.Instances.Add(s);
            return s;
        }

        internal override ISubsystem CreateImpl() => Create();
    }

    public abstract class SubsystemProvider
    {
        public bool running { get; internal set; }
    }

    public abstract class SubsystemProvider<TSubsystem> : SubsystemProvider
        where TSubsystem : SubsystemWithProvider, new()
    {
        public abstract void Start();
        public abstract void Stop();
        public abstract void Destroy();
    }
}
