package org.ktcs.overview

import org.koin.core.qualifier.named
import org.koin.dsl.module
import org.ktcs.api.overview.OverviewContribution
import org.ktcs.extension.InstalledDriverPanels
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.extension.web.WebContribution
import org.ktcs.extension.web.WebServerInfo

/**
 * The browser plant overview as a kTCS extension: it serves the page at `/`, lists every [OverviewContribution] of
 * every extension at `/overview/extensions.json` and serves their files. Its own panels and themes are contributions
 * like anybody else's.
 */
class OverviewExtension : KtcsExtension {
    override val name: String = "web-overview"

    override val settings = OverviewConfigKeys.all

    override fun module() = module {
        BuiltInContributions.all(OverviewExtension::class.java.classLoader).forEach { contribution ->
            single<OverviewContribution>(named("overview-${contribution.name}")) { contribution }
        }
        single<WebContribution>(named("web-overview")) {
            val config = getOrNull<KtcsConfig>() ?: KtcsConfig.defaults()
            val contributions = Contributions(getAll())
            OverviewRoutes(
                contributions,
                ThemeSelection.from(config, contributions),
                accessKeyRequired = getOrNull<WebServerInfo>()?.accessKeyRequired ?: false,
                driverPanel = { driver -> getOrNull<InstalledDriverPanels>()?.of(driver) },
            )
        }
    }
}
