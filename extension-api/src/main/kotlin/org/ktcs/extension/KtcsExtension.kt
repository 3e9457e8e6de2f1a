package org.ktcs.extension

import org.koin.core.module.Module
import org.ktcs.extension.config.Setting

/**
 * A kTCS extension: a vehicle driver, a strategy, a web panel, a channel to host systems. Extensions are found at
 * start-up with [java.util.ServiceLoader]: list the implementing class in
 * `META-INF/services/org.ktcs.extension.KtcsExtension` of the extension's jar (the name before kTCS 0.2,
 * `org.ktcs.extension.KtcsExtension`, is still read, with a warning).
 *
 * The kernel loads every extension's [module] after its own, so an extension can replace a default component by
 * declaring a definition of the same type. What an extension may ask of the kernel, with Koin's `get()`:
 * - the `api` services: [org.ktcs.api.service.KernelServices] and the services it groups, the strategies
 *   ([org.ktcs.api.routing.Router], [org.ktcs.api.scheduling.Scheduler], [org.ktcs.api.dispatching.Dispatcher]) and
 *   the [org.ktcs.api.dispatching.DispatchContext] a dispatcher works with;
 * - the loaded [org.ktcs.api.model.PlantModel] and the effective [org.ktcs.extension.config.KtcsConfig];
 * - [KernelDefaults] (the kernel's own strategies, to wrap or fall back on), [InstalledDriverPanels] and
 *   [org.ktcs.extension.web.WebServerInfo].
 *
 * What it may contribute: its [settings], [org.ktcs.api.driver.VehicleDriverFactory]s,
 * [org.ktcs.extension.web.WebContribution]s, [org.ktcs.api.overview.OverviewContribution]s, [ServedAddresses] and
 * replacements for the strategies above. Bind contributions of which every extension may add some (addresses, web
 * routes, overview contributions) under a qualifier of your own (`named("my-extension")`): Koin keeps
 * only the last unnamed definition of a type, so an unnamed one would replace another extension's or be replaced.
 */
public interface KtcsExtension {
    /** A short name for logs and error messages. */
    public val name: String

    /**
     * The settings this extension reads from the configuration. kTCS accepts them in the config file, as
     * environment variables and with `--set` like its own, lists them in `./ktcs config reference` and rejects a key
     * that neither kTCS nor an extension declares. Keys start with the extension's own prefix (`loopback.`, `xml.`).
     */
    public val settings: List<Setting<*>> get() = emptyList()

    /** The Koin definitions the extension contributes. */
    public fun module(): Module
}
