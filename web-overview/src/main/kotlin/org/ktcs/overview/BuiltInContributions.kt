package org.ktcs.overview

import org.ktcs.api.overview.OverviewContribution
import org.ktcs.api.overview.OverviewPanel
import org.ktcs.api.overview.OverviewTheme
import org.ktcs.api.overview.ThemeTarget

/** The panels and themes the overview ships with; each lives in its own class-path directory. */
object BuiltInContributions {
    private const val ROOT = "org/ktcs/overview/contributions"

    const val DEFAULT_VEHICLE_THEME = "default-vehicles"
    const val DEFAULT_LOCATION_THEME = "default-locations"

    fun all(classLoader: ClassLoader): List<OverviewContribution> = listOf(
        OverviewPanel("load-generator", "Load generator", "$ROOT/load-generator", classLoader = classLoader),
        OverviewPanel("statistics", "Statistics", "$ROOT/statistics", classLoader = classLoader),
        OverviewPanel(
            "resource-allocation",
            "Resources",
            "$ROOT/resource-allocation",
            classLoader = classLoader,
        ),
        theme(DEFAULT_VEHICLE_THEME, "Default", ThemeTarget.VEHICLES, classLoader),
        theme("high-contrast-vehicles", "High contrast", ThemeTarget.VEHICLES, classLoader),
        theme(DEFAULT_LOCATION_THEME, "Default", ThemeTarget.LOCATIONS, classLoader),
        theme("high-contrast-locations", "High contrast", ThemeTarget.LOCATIONS, classLoader),
    )

    private fun theme(name: String, title: String, target: ThemeTarget, classLoader: ClassLoader) =
        OverviewTheme(name, title, target, "$ROOT/$name", classLoader = classLoader)
}
