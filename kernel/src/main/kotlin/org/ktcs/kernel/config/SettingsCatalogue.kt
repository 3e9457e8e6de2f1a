package org.ktcs.kernel.config

import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.Setting
import org.ktcs.kernel.extension.Extensions

/** All the settings kTCS accepts: its own ([KtcsSettings]) followed by those its extensions declare. */
object SettingsCatalogue {
    /**
     * [KtcsSettings.all] and the settings of [extensions], in that order; a key declared twice is an
     * [ExtensionException] naming both declarers.
     */
    fun of(extensions: List<KtcsExtension>): List<Setting<*>> {
        val declarer = KtcsSettings.all.associate { it.key to "kTCS" }.toMutableMap()
        extensions.forEach { extension ->
            extension.settings.forEach { setting ->
                declarer[setting.key]?.let {
                    throw ExtensionException(
                        "extension '${extension.name}' declares the setting '${setting.key}', which $it declares too",
                    )
                }
                declarer[setting.key] = "extension '${extension.name}'"
            }
        }
        return KtcsSettings.all + extensions.flatMap { it.settings }
    }

    /** kTCS's settings and those of the extensions on the application's class path (not `extensions.directory`). */
    fun onClassPath(): List<Setting<*>> = of(Extensions.discover())
}
