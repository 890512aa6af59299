// Compile-only. Transcribed from Unity's C# reference source, branch 2022.3: Modules/Subsystems/ISubsystem.cs,
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
        public static void GetSubsystems<T>(List<T> subsystems) where T : ISubsystem => throw null;
    }
}

namespace UnityEngine.SubsystemsImplementation
{
    public abstract class SubsystemWithProvider : ISubsystem
    {
        public void Start() => throw null;
        protected abstract void OnStart();
        public void Stop() => throw null;
        protected abstract void OnStop();
        public void Destroy() => throw null;
        protected abstract void OnDestroy();
        public bool running => throw null;
    }

    public abstract class SubsystemWithProvider<TSubsystem, TSubsystemDescriptor, TProvider> : SubsystemWithProvider
        where TSubsystem : SubsystemWithProvider, new()
        where TSubsystemDescriptor : SubsystemDescriptorWithProvider
        where TProvider : SubsystemProvider<TSubsystem>
    {
        public TSubsystemDescriptor subsystemDescriptor => throw null;
        protected override void OnStart() => throw null;
        protected override void OnStop() => throw null;
        protected override void OnDestroy() => throw null;
    }

    public abstract class SubsystemDescriptorWithProvider : ISubsystemDescriptor
    {
        public string id { get => throw null; set => throw null; }
        ISubsystem ISubsystemDescriptor.Create() => throw null;
    }

    public class SubsystemDescriptorWithProvider<TSubsystem, TProvider> : SubsystemDescriptorWithProvider
        where TSubsystem : SubsystemWithProvider, new()
        where TProvider : SubsystemProvider<TSubsystem>
    {
        public TSubsystem Create() => throw null;
    }

    public abstract class SubsystemProvider
    {
        public bool running => throw null;
    }

    public abstract class SubsystemProvider<TSubsystem> : SubsystemProvider
        where TSubsystem : SubsystemWithProvider, new()
    {
        public abstract void Start();
        public abstract void Stop();
        public abstract void Destroy();
    }
}
