package org.ktcs.overview

import org.ktcs.extension.config.stringSetting

/** The browser overview's configuration keys (`overview.*`), declared by [OverviewExtension]. */
object OverviewConfigKeys {
    val vehicleTheme = stringSetting(
        "overview.vehicleTheme",
        "default-vehicles",
        "Name of the theme the browser overview draws vehicles with (default-vehicles, high-contrast-vehicles, or " +
            "one an extension adds).",
    )
    val locationTheme = stringSetting(
        "overview.locationTheme",
        "default-locations",
        "Name of the theme the browser overview draws locations with (default-locations, high-contrast-locations, " +
            "or one an extension adds).",
    )

    val all = listOf(vehicleTheme, locationTheme)
}
