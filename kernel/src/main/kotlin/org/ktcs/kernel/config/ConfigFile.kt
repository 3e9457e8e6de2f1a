package org.ktcs.kernel.config

import org.ktcs.extension.config.KtcsConfig
import org.ktcs.extension.config.Setting

/** Writes the documented config file: every setting with its description and default, commented out. */
object ConfigFile {
    fun render(settings: List<Setting<*>> = SettingsCatalogue.onClassPath()): String = buildString {
        appendLine("# kTCS configuration. Every setting is listed with its default; uncomment a line to change it.")
        appendLine("# Precedence, lowest first: defaults, this file, environment variables, --set key=value.")
        appendLine("# Environment variables: KTCS_ + the key in capitals, dots as underscores (KTCS_WEB_PORT=8080).")
        settings.forEach { setting ->
            appendLine()
            appendLine("# ${setting.description}")
            appendLine("#${setting.key} = ${setting.defaultText()}")
        }
    }

    /** The effective configuration, one `key = value  # source` line per setting. */
    fun describe(config: KtcsConfig, settings: List<Setting<*>> = SettingsCatalogue.onClassPath()): String =
        settings.joinToString("\n") { "${it.key} = ${config[it]}  # ${config.sourceOf(it)}" }
}
