package org.ktcs.extension.config

/**
 * The effective configuration: a value for every known setting, kTCS's and the extensions'. Immutable; the kernel
 * builds it from the defaults, the config file, the environment and `--set` options.
 */
public class KtcsConfig(private val values: Map<String, Any>, public val sources: Map<String, String>) {
    /** The value of [setting]. */
    @Suppress("UNCHECKED_CAST")
    public operator fun <T : Any> get(setting: Setting<T>): T = values[setting.key] as T? ?: setting.default

    /** Where the value of [setting] came from: "default", the config file, an environment variable or `--set`. */
    public fun sourceOf(setting: Setting<*>): String = sources[setting.key] ?: "default"

    public companion object {
        /** Every setting at its default. */
        public fun defaults(): KtcsConfig = KtcsConfig(emptyMap(), emptyMap())
    }
}
