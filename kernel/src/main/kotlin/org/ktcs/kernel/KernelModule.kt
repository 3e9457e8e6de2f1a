package org.ktcs.kernel

import org.koin.core.module.Module
import org.koin.dsl.module
import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.dispatching.RecoveryEvaluator
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.PlantModel
import org.ktcs.api.routing.Router
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.api.service.KernelServices
import org.ktcs.extension.InstalledDriverPanels
import org.ktcs.extension.KernelDefaults
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.extension.config.positiveDoubleSetting
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.config.WatchdogSettings
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.context.VehicleTimeClock
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.core.KernelOptions
import org.ktcs.kernel.core.WatchdogOptions
import org.ktcs.kernel.dispatching.DefaultDispatcher
import org.ktcs.kernel.dispatching.DefaultRecoveryEvaluator
import org.ktcs.kernel.dispatching.DispatcherConfiguration
import org.ktcs.kernel.persistence.PublishedModelFile
import org.ktcs.kernel.routing.DefaultRouter
import org.ktcs.kernel.routing.RouterConfiguration
import org.ktcs.kernel.scheduling.DefaultScheduler
import org.ktcs.kernel.services.StandardKernelServices
import java.nio.file.Path
import java.util.ServiceLoader

/**
 * The kernel's Koin definitions. Router, Scheduler, Dispatcher and RecoveryEvaluator are defined by type, so an
 * extension's module that defines one of these types again replaces the default; [KernelDefaults] keeps the default
 * dispatcher reachable for one that wraps it. What extensions may ask for is listed on
 * [org.ktcs.extension.KtcsExtension].
 */
fun kernelModule(config: KtcsConfig, model: PlantModel, context: KernelContext): Module = module {
    val options = kernelOptions(config)
    single { config }
    single { model }
    single<KernelContext> { context }
    single { routerConfiguration(config) }
    single { dispatcherConfiguration(config) }
    single<Router> { DefaultRouter(get()) }
    single<Scheduler> { DefaultScheduler(get(), VehicleTimeClock(get<KernelContext>(), options.vehicleTimeFactor)) }
    single<RecoveryEvaluator> { DefaultRecoveryEvaluator(config[KtcsSettings.dispatcherRecoveryThreshold]) }
    single<DispatchContext> { get<KernelCore>().dispatchContext }
    single<KernelDefaults> {
        val scope = this
        object : KernelDefaults {
            override fun dispatcher(): Dispatcher = DefaultDispatcher(scope.get(), scope.get(), scope.get())
        }
    }
    single<Dispatcher> { get<KernelDefaults>().dispatcher() }
    single {
        val factories = getAll<VehicleDriverFactory>() + ServiceLoader.load(VehicleDriverFactory::class.java).toList()
        KernelCore(
            context = get(),
            model = get(),
            router = get(),
            scheduler = get(),
            dispatcherProvider = { get<Dispatcher>() },
            recoveryEvaluator = get(),
            driverFactories = factories.distinctBy { it.name },
            options = options,
        )
    }
    single { PublishedModelFile(Path.of(config[KtcsSettings.dataDirectory])) }
    single<KernelServices> { StandardKernelServices(get(), get()) }
    single<InstalledDriverPanels> {
        InstalledDriverPanels { driver -> get<KernelCore>().controllers.factory(driver)?.panel }
    }
}

fun kernelOptions(config: KtcsConfig) = KernelOptions(
    resourceManagement = config[KtcsSettings.kernelResourceManagement],
    enableDriversOnStart = config[KtcsSettings.kernelEnableDrivers],
    initialIntegrationLevel = config[KtcsSettings.kernelInitialIntegrationLevel],
    redispatchIntervalMillis = config[KtcsSettings.dispatcherRedispatchInterval],
    newOrderDispatchDelayMillis = config[KtcsSettings.dispatcherNewOrderDelay],
    sweepIntervalMillis = config[KtcsSettings.orderPoolSweepInterval],
    sweepAgeMillis = config[KtcsSettings.orderPoolSweepAge],
    deadlockCheckIntervalMillis = config[KtcsSettings.kernelDeadlockCheckInterval],
    vehicleTimeFactor = config[loopbackTimeFactor],
    watchdog = WatchdogOptions(
        strandedVehicleCheckIntervalMillis = config[WatchdogSettings.strandedVehicleCheckInterval],
        strandedVehicleMillis = config[WatchdogSettings.strandedVehicleDuration],
        orderCheckIntervalMillis = config[WatchdogSettings.transportOrderCheckInterval],
        idleOrderMillis = config[WatchdogSettings.idleTransportOrderDuration],
        reportPositionOffRoute = config[WatchdogSettings.positionOffRoute],
    ),
)

// Declared and documented by the loopback extension; read here because simulated vehicles move that much faster than
// the kernel clock (without the extension the key is never set: real vehicles, factor 1).
private val loopbackTimeFactor = positiveDoubleSetting("loopback.timeFactor", 1.0, "See the loopback extension.")

fun routerConfiguration(config: KtcsConfig) = RouterConfiguration(
    algorithm = config[KtcsSettings.routerAlgorithm],
    edgeEvaluators = config[KtcsSettings.routerEdgeEvaluators].values,
    explicitPropertiesDefaultValue = config[KtcsSettings.routerExplicitDefault],
    routeComputationLimit = config[KtcsSettings.routerComputationLimit],
    operationPointSurcharge = config[KtcsSettings.routerOperationPointSurcharge],
)

fun dispatcherConfiguration(config: KtcsConfig) = DispatcherConfiguration(
    orderPriorities = config[KtcsSettings.dispatcherOrderPriorities].values,
    vehiclePriorities = config[KtcsSettings.dispatcherVehiclePriorities].values,
    vehicleCandidatePriorities = config[KtcsSettings.dispatcherVehicleCandidatePriorities].values,
    orderCandidatePriorities = config[KtcsSettings.dispatcherOrderCandidatePriorities].values,
    orderCandidateWindow = config[KtcsSettings.dispatcherOrderCandidateWindow],
    parkIdleVehicles = config[KtcsSettings.dispatcherParkIdleVehicles],
    rechargeIdleVehicles = config[KtcsSettings.dispatcherRechargeIdleVehicles],
    keepRechargingUntilFullyCharged = config[KtcsSettings.dispatcherKeepRecharging],
)
