package org.ktcs.kernel.app

import org.ktcs.extension.config.Setting
import org.ktcs.kernel.config.SettingsCatalogue

/**
 * `docs/configuration.md`, generated from the settings' declarations so it cannot drift from the code:
 * `./ktcs config reference > docs/configuration.md`.
 */
object ConfigReference {
    const val REGENERATE = "./ktcs config reference > docs/configuration.md"

    fun render(settings: List<Setting<*>> = SettingsCatalogue.onClassPath()): String = buildString {
        appendLine("# Configuration reference")
        appendLine()
        appendLine(
            "<!-- Generated from KtcsSettings and the extensions' settings by `$REGENERATE`; do not edit by hand. -->",
        )
        appendLine()
        appendLine(
            "Settings come from, in rising precedence: the defaults below, the config file (`--config FILE`, " +
                "otherwise `config/ktcs.conf` if it exists), environment variables (`KTCS_` + the key in capitals " +
                "with dots as underscores, e.g. `KTCS_WEB_PORT`) and `--set key=value` options. " +
                "`./ktcs config` prints the effective values and where each comes from.",
        )
        settings.groupBy { it.key.substringBefore('.') }.forEach { (section, members) ->
            appendLine()
            appendLine("## `$section.*`")
            appendLine()
            appendLine("| Key | Default | Environment variable | Meaning |")
            appendLine("|---|---|---|---|")
            members.forEach { setting ->
                val default = setting.defaultText().replace("|", "\\|")
                appendLine("| `${setting.key}` | `$default` | `${environmentName(setting)}` | ${setting.description} |")
            }
        }
    }

    private fun environmentName(setting: Setting<*>) = "KTCS_" + setting.key.uppercase().replace('.', '_')
}
