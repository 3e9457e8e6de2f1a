package org.ktcs.overview

import org.ktcs.api.overview.ThemeTarget
import org.ktcs.extension.config.ConfigException
import org.ktcs.extension.config.KtcsConfig

/** The theme the configuration chose for each target, checked against the themes that exist. */
data class ThemeSelection(val vehicleTheme: String, val locationTheme: String) {
    companion object {
        fun from(config: KtcsConfig, contributions: Contributions) = ThemeSelection(
            vehicleTheme = checked(config[OverviewConfigKeys.vehicleTheme], ThemeTarget.VEHICLES, contributions),
            locationTheme = checked(config[OverviewConfigKeys.locationTheme], ThemeTarget.LOCATIONS, contributions),
        )

        private fun checked(name: String, target: ThemeTarget, contributions: Contributions): String {
            val known = contributions.themes(target).map { it.name }
            if (name !in known) {
                val setting = when (target) {
                    ThemeTarget.VEHICLES -> OverviewConfigKeys.vehicleTheme
                    ThemeTarget.LOCATIONS -> OverviewConfigKeys.locationTheme
                }
                val key = setting.key
                throw ConfigException(
                    "$key: unknown ${target.name.lowercase()} theme '$name'; known: ${known.joinToString()}",
                )
            }
            return name
        }
    }
}
