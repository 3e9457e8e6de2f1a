package org.ktcs.examples.overview

import org.koin.core.module.Module
import org.koin.core.qualifier.named
import org.koin.dsl.module
import org.ktcs.api.overview.OverviewContribution
import org.ktcs.api.overview.OverviewPanel
import org.ktcs.api.overview.OverviewTheme
import org.ktcs.api.overview.ThemeTarget
import org.ktcs.extension.KtcsExtension

// snippet:overview-extension
/**
 * Adds a panel listing every vehicle's energy and a vehicle theme that colours vehicles by energy to the browser
 * overview. Select the theme with `overview.vehicleTheme=energy`.
 */
class OverviewExamplesExtension : KtcsExtension {
    override val name: String = "overview-examples"

    override fun module(): Module = module {
        single<OverviewContribution>(named(PANEL)) {
            OverviewPanel(
                name = PANEL,
                title = "Fleet energy",
                resourceDirectory = "org/ktcs/examples/overview/fleet-energy",
                classLoader = OverviewExamplesExtension::class.java.classLoader,
            )
        }
        single<OverviewContribution>(named(THEME)) {
            OverviewTheme(
                name = THEME,
                title = "Energy",
                target = ThemeTarget.VEHICLES,
                resourceDirectory = "org/ktcs/examples/overview/energy-theme",
                classLoader = OverviewExamplesExtension::class.java.classLoader,
            )
        }
    }

    companion object {
        const val PANEL = "fleet-energy"
        const val THEME = "energy"
    }
}
// end-snippet
