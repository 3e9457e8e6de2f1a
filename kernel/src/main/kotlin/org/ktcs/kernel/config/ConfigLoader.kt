package org.ktcs.kernel.config

import org.ktcs.extension.config.ConfigException
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.extension.config.Setting
import java.nio.file.Files
import java.nio.file.Path

/**
 * Builds the effective configuration from, in rising precedence: the defaults, the config file, environment
 * variables (`KTCS_` + the key in capitals with `.` as `_`, e.g. `KTCS_WEB_PORT`) and `--set key=value` options.
 * Unknown keys and bad values are rejected with a [ConfigException] naming them.
 *
 * [settings] are the keys it knows, by default kTCS's and those of the extensions on the class path; the launcher
 * passes those of the extensions it installed (see [SettingsCatalogue]).
 */
class ConfigLoader(private val settings: List<Setting<*>> = SettingsCatalogue.onClassPath()) {
    private val byKey = settings.associateBy { it.key }
    private val byEnvironmentName = settings.associateBy { environmentName(it.key) }

    /**
     * The configuration from [file], [environment] and [overrides]. With [ignoreUnknown], keys this loader does not
     * know are skipped instead of rejected: the launcher reads kTCS's own settings that way first, to find the
     * extensions, whose settings it then reads with a loader that knows them.
     */
    fun load(
        file: Path?,
        environment: Map<String, String>,
        overrides: List<String>,
        ignoreUnknown: Boolean = false,
    ): KtcsConfig {
        val values = mutableMapOf<String, Any>()
        val sources = mutableMapOf<String, String>()
        fun put(setting: Setting<*>?, raw: String, source: String) {
            if (setting == null) return
            values[setting.key] = setting.parse(raw, source)
            sources[setting.key] = source
        }
        file?.let { path ->
            readFile(path).forEach { (line, key, raw) ->
                put(known(key, "$path:$line", ignoreUnknown), raw, "$path:$line")
            }
        }
        environment.filterKeys {
            it.startsWith(ENV_PREFIX) && it !in LAUNCHER_VARIABLES
        }.toSortedMap().forEach { (name, raw) ->
            val setting = byEnvironmentName[name]
                ?: if (ignoreUnknown) {
                    return@forEach
                } else {
                    throw ConfigException(
                        "unknown environment variable $name: kTCS knows ${byEnvironmentName.keys.joinToString()}",
                    )
                }
            put(setting, raw, "environment variable $name")
        }
        overrides.forEach { option ->
            val (key, raw) = splitAssignment(option) ?: throw ConfigException("--set '$option': expected key=value")
            put(known(key, "--set $option", ignoreUnknown), raw, "--set $key")
        }
        return KtcsConfig(values, sources)
    }

    private fun known(key: String, source: String, ignoreUnknown: Boolean): Setting<*>? = byKey[key]
        ?: if (ignoreUnknown) {
            null
        } else {
            throw ConfigException(
                "$source: unknown setting '$key'" + (
                    suggestionFor(key)?.let {
                        " (did you mean '$it'?)"
                    } ?: ""
                    ),
            )
        }

    private fun suggestionFor(key: String): String? =
        byKey.keys.minByOrNull { editDistance(it.lowercase(), key.lowercase()) }
            ?.takeIf { editDistance(it.lowercase(), key.lowercase()) <= MAX_SUGGESTION_DISTANCE }

    private fun readFile(path: Path): List<Triple<Int, String, String>> {
        if (!Files.isRegularFile(path)) throw ConfigException("config file $path does not exist")
        return Files.readAllLines(path).mapIndexedNotNull { index, text ->
            val line = text.trim()
            if (line.isEmpty() || line.startsWith("#")) return@mapIndexedNotNull null
            val (key, raw) = splitAssignment(line)
                ?: throw ConfigException("$path:${index + 1}: expected 'key = value', found '$line'")
            Triple(index + 1, key, raw)
        }
    }

    private fun splitAssignment(text: String): Pair<String, String>? {
        val at = text.indexOf('=')
        if (at <= 0) return null
        return text.substring(0, at).trim() to text.substring(at + 1).trim()
    }

    companion object {
        const val ENV_PREFIX = "KTCS_"

        /** The `ktcs` launcher's own variables (JVM settings, class-data sharing), which the JVM it starts inherits. */
        val LAUNCHER_VARIABLES = setOf("KTCS_JVM_DEFAULTS", "KTCS_CDS")
        private const val MAX_SUGGESTION_DISTANCE = 2

        /** The environment variable that sets [key], e.g. `KTCS_WEB_BINDADDRESS` for `web.bindAddress`. */
        fun environmentName(key: String): String = ENV_PREFIX + key.replace('.', '_').uppercase()
    }
}

/** Levenshtein distance: how many single-character edits turn [a] into [b]. */
internal fun editDistance(a: String, b: String): Int {
    var previous = IntArray(b.length + 1) { it }
    for (i in a.indices) {
        val current = IntArray(b.length + 1)
        current[0] = i + 1
        for (j in b.indices) {
            val substitution = previous[j] + if (a[i] == b[j]) 0 else 1
            current[j + 1] = minOf(substitution, previous[j + 1] + 1, current[j] + 1)
        }
        previous = current
    }
    return previous[b.length]
}
