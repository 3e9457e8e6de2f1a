package org.ktcs.kernel.config

/** The effective configuration: a value for every known setting. Immutable. */
class KtcsConfig internal constructor(private val values: Map<String, Any>, val sources: Map<String, String>) {
    /** The value of [setting]. */
    @Suppress("UNCHECKED_CAST")
    operator fun <T : Any> get(setting: Setting<T>): T = values[setting.key] as T? ?: setting.default

    /** Where the value of [setting] came from: "default", the config file, an environment variable or `--set`. */
    fun sourceOf(setting: Setting<*>): String = sources[setting.key] ?: "default"

    companion object {
        /** Every setting at its default. */
        fun defaults(): KtcsConfig = KtcsConfig(emptyMap(), emptyMap())
    }
}
