package org.ktcs.overview

import org.ktcs.api.overview.ThemeTarget
import org.ktcs.kernel.config.ConfigException
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings

/** The theme the configuration chose for each target, checked against the themes that exist. */
data class ThemeSelection(val vehicleTheme: String, val locationTheme: String) {
    companion object {
        fun from(config: KtcsConfig, contributions: Contributions) = ThemeSelection(
            vehicleTheme = checked(config[KtcsSettings.overviewVehicleTheme], ThemeTarget.VEHICLES, contributions),
            locationTheme = checked(config[KtcsSettings.overviewLocationTheme], ThemeTarget.LOCATIONS, contributions),
        )

        private fun checked(name: String, target: ThemeTarget, contributions: Contributions): String {
            val known = contributions.themes(target).map { it.name }
            if (name !in known) {
                val key = if (target == ThemeTarget.VEHICLES) "overview.vehicleTheme" else "overview.locationTheme"
                throw ConfigException(
                    "$key: unknown ${target.name.lowercase()} theme '$name'; known: ${known.joinToString()}",
                )
            }
            return name
        }
    }
}
