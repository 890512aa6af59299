// Test double (attributes carry their arguments). Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Runtime/Export/Serialization/Serialization.cs (SerializeField, SerializeReference, ISerializationCallbackReceiver), Runtime/Export/PropertyDrawer/PropertyAttribute.cs
//   (PropertyAttribute, TooltipAttribute, HeaderAttribute), Runtime/Export/Scripting/Attributes.cs (AddComponentMenu,
//   DisallowMultipleComponent, CreateAssetMenuAttribute, ContextMenu, HideInInspector), Runtime/Export/Scripting/RuntimeInitializeOnLoadAttribute.cs,
//   Runtime/Export/Application/BeforeRenderHelper.cs (BeforeRenderOrderAttribute)
// Attribute targets as declared there, so misplaced attributes fail here as they would in Unity.
using System;

namespace UnityEngine
{
    public sealed class SerializeField : Attribute
    {
    }

    /// <summary>Serializes a field as a reference (polymorphic plain C# classes, null). The double's serializer treats it as a
    /// field to write (JsonUtility ignores it in Unity; nothing here reads it).</summary>
    [AttributeUsage(AttributeTargets.Field)]
    public sealed class SerializeReference : Attribute
    {
        public SerializeReference() { }
    }

    /// <summary>Unity calls OnBeforeSerialize before it writes the object and OnAfterDeserialize after it has read it (the
    /// double calls them where a driver says an asset is saved or loaded: UnityDouble.Assets).</summary>
    public interface ISerializationCallbackReceiver
    {
        void OnBeforeSerialize();
        void OnAfterDeserialize();
    }

    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public abstract class PropertyAttribute : Attribute
    {
    }

    [AttributeUsage(AttributeTargets.All, Inherited = true, AllowMultiple = false)]
    public class TooltipAttribute : PropertyAttribute
    {
        public readonly string tooltip;
        public TooltipAttribute(string tooltip) => this.tooltip = tooltip;
    }

    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = true)]
    public class HeaderAttribute : PropertyAttribute
    {
        public readonly string header;
        public HeaderAttribute(string header) => this.header = header;
    }

    public sealed class AddComponentMenu : Attribute
    {
        public AddComponentMenu(string menuName) => componentMenu = menuName;
        public string componentMenu { get; }
    }

    public sealed class HideInInspector : Attribute
    {
    }

    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public sealed class DisallowMultipleComponent : Attribute
    {
    }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = false, Inherited = false)]
    public sealed class CreateAssetMenuAttribute : Attribute
    {
        public string menuName { get; set; }
        public string fileName { get; set; }
        public int order { get; set; }
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class ContextMenu : Attribute
    {
        public ContextMenu(string itemName) => menuItem = itemName;
        public readonly string menuItem;
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = false)]
    public class RuntimeInitializeOnLoadMethodAttribute : Attribute
    {
        public RuntimeInitializeOnLoadMethodAttribute(RuntimeInitializeLoadType loadType) => this.loadType = loadType;
        public RuntimeInitializeLoadType loadType { get; }
    }

    /// <summary>AddComponent adds the required components first (when the GameObject lacks them).</summary>
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true, Inherited = true)]
    public sealed class RequireComponent : Attribute
    {
        public Type m_Type0;

        public RequireComponent(Type requiredComponent) => m_Type0 = requiredComponent;
    }

    /// <summary>Scripts of a class with this attribute run before (negative) or after (positive) those without, in every phase.</summary>
    [AttributeUsage(AttributeTargets.Class)]
    public class DefaultExecutionOrder : Attribute
    {
        public DefaultExecutionOrder(int order) => this.order = order;
        public int order { get; }
    }

    /// <summary>The order of a method subscribed to Application.onBeforeRender: lower first, 0 without the attribute.</summary>
    [AttributeUsage(AttributeTargets.Method)]
    public class BeforeRenderOrderAttribute : Attribute
    {
        public int order { get; private set; }

        public BeforeRenderOrderAttribute(int order) => this.order = order;
    }

    public enum RuntimeInitializeLoadType
    {
        AfterSceneLoad = 0,
        BeforeSceneLoad = 1,
        AfterAssembliesLoaded = 2,
        BeforeSplashScreen = 3,
        SubsystemRegistration = 4,
    }
}
