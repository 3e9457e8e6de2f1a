package org.ktcs.kernel.config

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.kernel.dispatching.CandidatePriority
import org.ktcs.kernel.dispatching.OrderPriority
import org.ktcs.kernel.dispatching.VehiclePriority
import org.ktcs.kernel.routing.EdgeEvaluator
import org.ktcs.kernel.routing.RoutingAlgorithm
import org.ktcs.kernel.vehicles.ResourceManagement

/** Every setting kTCS knows. A key that is not listed here is rejected wherever it appears. */
object KtcsSettings {
    private const val MAX_PORT = 65535

    val webBindAddress = stringSetting(
        "web.bindAddress",
        "0.0.0.0",
        "Address the web API and the browser overview listen on (0.0.0.0: all interfaces, 127.0.0.1: this machine " +
            "only).",
    )
    val webPort =
        intSetting(
            "web.port",
            55200,
            0..MAX_PORT,
            "TCP port of the web API and the browser overview (0: any free port).",
        )
    val webAccessKey = Setting(
        "web.accessKey",
        "",
        "Key a web API client must send in the X-Api-Access-Key header (empty: no key needed).",
        { it },
    )
    val webAllowedOrigins = Setting(
        "web.allowedOrigins",
        "",
        "Origins whose web pages may use the web API, comma-separated (e.g. https://mes.example.com), or * for any; " +
            "kTCS's own pages always may (empty: no others).",
        { it },
    )
    val webAllowLocalShutdown = booleanSetting(
        "web.allowLocalShutdown",
        false,
        "Let DELETE /v1/kernel shut kTCS down from this machine without the access key (it always needs one of the two).",
    )
    val webMaxRequestBodySize = longSetting(
        "web.maxRequestBodySize",
        200,
        1L..10_000L,
        "The largest request body the web API reads, in MB; larger ones get 413.",
    )
    val webSocketBufferSize = intSetting(
        "web.webSocketBufferSize",
        1000,
        1..1_000_000,
        "Events queued for one WebSocket client; a client that falls further behind is told it missed events and " +
            "gets fresh snapshots.",
    )
    val xmlOrdersPort =
        intSetting("xml.orders.port", 55555, 0..MAX_PORT, "TCP port of the XML order channel (0: any free port).")
    val xmlStatusPort =
        intSetting("xml.status.port", 44444, 0..MAX_PORT, "TCP port of the XML status channel (0: any free port).")
    val xmlBindAddress =
        stringSetting("xml.bindAddress", "0.0.0.0", "Address the XML order and status channels listen on.")
    val xmlOrdersIdleTimeout = longSetting(
        "xml.orders.idleTimeout",
        10_000,
        1L..3_600_000L,
        "Milliseconds an XML order channel client has to send its whole telegram; a slower one is closed without a " +
            "receipt.",
    )
    val xmlOrdersMaxConnections = intSetting(
        "xml.orders.maxConnections",
        100,
        1..100_000,
        "XML order channel connections served at once; more are refused with a line saying so.",
    )
    val xmlStatusMaxConnections = intSetting(
        "xml.status.maxConnections",
        100,
        1..100_000,
        "XML status channel clients served at once; more are refused with a line saying so.",
    )
    val xmlOrdersInputLimit =
        intSetting("xml.orders.inputLimit", 102_400, 1..67_108_864, "The largest XML order telegram, in bytes.")
    val xmlStatusSeparator =
        stringSetting("xml.status.separator", "|", "Written after every message on the XML status channel.")
    val xmlStatusBufferSize = intSetting(
        "xml.status.bufferSize",
        1000,
        1..1_000_000,
        "Status messages queued for one client; a client that falls further behind is dropped.",
    )
    val xmlScriptsDirectory =
        stringSetting("xml.scriptsDirectory", "scripts", "Directory of the .tcs batch scripts that XML telegrams name.")

    val loopbackPlaceUnpositionedVehicles = booleanSetting(
        "loopback.placeUnpositionedVehicles",
        true,
        "Place a simulated vehicle without loopback:initialPosition on a free park position (else a free point) " +
            "when it starts, and say where in a notification.",
    )
    val loopbackTimeFactor = positiveDoubleSetting(
        "loopback.timeFactor",
        1.0,
        "How much faster than real time the simulated loopback vehicles move (2.0: twice as fast).",
    )
    val logLevel = enumSetting(
        "log.level",
        LogLevel.INFO,
        "Log level of kTCS's own loggers: ERROR, WARN, INFO, DEBUG or TRACE. Libraries log warnings and errors only.",
    )

    val kernelEnableDrivers = booleanSetting(
        "kernel.enableDriversOnStart",
        true,
        "Enable every vehicle's driver when kTCS starts (openTCS: kernelapp.autoEnableDriversOnStartup, default " +
            "false there).",
    )
    val kernelInitialIntegrationLevel = enumSetting(
        "kernel.initialIntegrationLevel",
        IntegrationLevel.TO_BE_UTILIZED,
        "Integration level of every vehicle at start: TO_BE_IGNORED, TO_BE_NOTICED, TO_BE_RESPECTED or " +
            "TO_BE_UTILIZED (takes orders).",
    )
    val kernelDeadlockCheckInterval = longSetting(
        "kernel.deadlockCheckInterval",
        1000,
        0L..3_600_000L,
        "Milliseconds between checks for vehicles waiting for each other in a cycle; a deadlock is reported and " +
            "broken by rerouting (0: off).",
    )
    val kernelResourceManagement = enumSetting(
        "kernel.vehicleResourceManagement",
        ResourceManagement.LENGTH_RESPECTED,
        "What vehicles keep behind them: LENGTH_RESPECTED (the paths their length still covers) or LENGTH_IGNORED (only the point they stand on).",
    )
    val orderPoolSweepInterval =
        longSetting(
            "orderpool.sweepInterval",
            60_000,
            1L..Long.MAX_VALUE,
            "Milliseconds between sweeps of old final " +
                "orders.",
        )
    val orderPoolSweepAge =
        longSetting(
            "orderpool.sweepAge",
            86_400_000,
            0L..Long.MAX_VALUE,
            "Milliseconds a final order is kept before " +
                "a sweep removes it.",
        )

    val routerAlgorithm =
        enumSetting(
            "router.algorithm",
            RoutingAlgorithm.DIJKSTRA,
            "Shortest-path algorithm: DIJKSTRA, BELLMAN_FORD " +
                "or FLOYD_WARSHALL.",
        )
    val routerEdgeEvaluators = enumListSetting(
        "router.edgeEvaluators",
        listOf(EdgeEvaluator.DISTANCE),
        "Route costs, summed: DISTANCE, TRAVELTIME, HOPS, EXPLICIT_PROPERTIES, BOUNDING_BOX.",
    )
    val routerExplicitDefault = longSetting(
        "router.explicitProperties.defaultValue",
        1_000_000,
        0L..Long.MAX_VALUE,
        "Cost of a path without a tcs:routingCostForward/Reverse property under EXPLICIT_PROPERTIES.",
    )
    val routerComputationLimit = intSetting(
        "router.routeComputationLimit",
        10,
        1..1000,
        "The most routes computed " +
            "for one route query.",
    )

    val dispatcherRedispatchInterval = longSetting(
        "dispatcher.idleVehicleRedispatchingInterval",
        10_000,
        0L..3_600_000L,
        "Milliseconds between safety-net dispatcher runs; it also runs whenever an order or a vehicle becomes " +
            "ready (0: off).",
    )
    val dispatcherNewOrderDelay = longSetting(
        "dispatcher.newOrderDelay",
        10,
        0L..1_000L,
        "Milliseconds a dispatcher run waits after a new order became dispatchable, so that orders created in " +
            "quick succession share one run instead of each paying for a pass over every waiting order (0: at once).",
    )
    val dispatcherOrderPriorities = enumListSetting(
        "dispatcher.orderPriorities",
        listOf(OrderPriority.BY_DEADLINE),
        "How orders are ranked: BY_AGE, BY_DEADLINE, DEADLINE_AT_RISK_FIRST, BY_NAME.",
    )
    val dispatcherVehiclePriorities = enumListSetting(
        "dispatcher.vehiclePriorities",
        listOf(VehiclePriority.IDLE_FIRST, VehiclePriority.BY_ENERGY_LEVEL),
        "How vehicles are ranked: IDLE_FIRST, BY_ENERGY_LEVEL, BY_NAME.",
    )
    val dispatcherVehicleCandidatePriorities = enumListSetting(
        "dispatcher.vehicleCandidatePriorities",
        listOf(CandidatePriority.IDLE_FIRST, CandidatePriority.BY_ENERGY_LEVEL),
        "How an order picks among vehicles: " + CandidatePriority.entries.joinToString(", ") + ".",
    )
    val dispatcherOrderCandidatePriorities = enumListSetting(
        "dispatcher.orderCandidatePriorities",
        listOf(CandidatePriority.BY_DEADLINE),
        "How a vehicle picks among orders: the same keys as dispatcher.vehicleCandidatePriorities.",
    )
    val dispatcherParkIdleVehicles =
        booleanSetting(
            "dispatcher.parkIdleVehicles",
            true,
            "Send idle vehicles to park positions (openTCS default: " +
                "false).",
        )
    val dispatcherRechargeIdleVehicles = booleanSetting(
        "dispatcher.rechargeIdleVehicles",
        true,
        "Send idle vehicles with degraded energy to recharge (openTCS default: false).",
    )
    val dispatcherKeepRecharging = booleanSetting(
        "dispatcher.keepRechargingUntilFullyCharged",
        true,
        "A charging vehicle takes no orders before it is fully recharged.",
    )
    val dispatcherRecoveryThreshold = doubleSetting(
        "dispatcher.recoveryThreshold",
        0.7,
        0.0..1.0,
        "Share of full energy at which a charging vehicle may take orders again (openTCS 4.x recovery evaluator).",
    )

    val loopbackOperatingTime = longSetting(
        "loopback.operatingTime",
        5000,
        0L..3_600_000L,
        "Simulated milliseconds an operation takes (vehicle property loopback:operatingTime overrides).",
    )
    val loopbackAcceleration =
        positiveDoubleSetting(
            "loopback.acceleration",
            500.0,
            "Simulated acceleration in mm/s² (vehicle property " +
                "loopback:acceleration overrides).",
        )
    val loopbackDeceleration =
        positiveDoubleSetting(
            "loopback.deceleration",
            500.0,
            "Simulated deceleration in mm/s² (vehicle property " +
                "loopback:deceleration overrides).",
        )
    val loopbackRechargeRate =
        doubleSetting(
            "loopback.rechargePercentPerSecond",
            1.0,
            0.0..100.0,
            "Percent of energy a charging simulated " +
                "vehicle gains per second.",
        )
    val loopbackEnergyDrain = doubleSetting(
        "loopback.energyDrainPercentPerKm",
        10.0,
        0.0..10_000.0,
        "Percent of energy a simulated vehicle uses per kilometre driven (openTCS's never drains).",
    )
    val loopbackPositionReportInterval = longSetting(
        "loopback.positionReportInterval",
        500,
        0L..60_000L,
        "Milliseconds of real (kernel-clock) time between precise-position reports while driving, whatever loopback.timeFactor (0: only at points).",
    )
    val overviewVehicleTheme = stringSetting(
        "overview.vehicleTheme",
        "default-vehicles",
        "Name of the theme the browser overview draws vehicles with (default-vehicles, high-contrast-vehicles, or " +
            "one an extension adds).",
    )
    val overviewLocationTheme = stringSetting(
        "overview.locationTheme",
        "default-locations",
        "Name of the theme the browser overview draws locations with (default-locations, high-contrast-locations, " +
            "or one an extension adds).",
    )

    val extensionsDirectory = stringSetting(
        "extensions.directory",
        "extensions",
        "Directory of extension jars loaded at start (relative to the working directory); a missing directory is " +
            "fine unless set explicitly.",
    )

    val dataDirectory = stringSetting(
        "kernel.dataDirectory",
        "data",
        "Directory where kTCS keeps what it must not lose (the published plant model, its state store, log files); " +
            "relative to the working directory, created on first use.",
    )

    val all: List<Setting<*>> = listOf(
        webBindAddress,
        webPort,
        webAccessKey,
        webAllowedOrigins,
        webAllowLocalShutdown,
    ) + TlsSettings.all + listOf(
        webMaxRequestBodySize,
        webSocketBufferSize,
        xmlOrdersPort,
        xmlStatusPort,
        xmlBindAddress,
        xmlOrdersIdleTimeout,
        xmlOrdersInputLimit,
        xmlOrdersMaxConnections,
        xmlStatusSeparator,
        xmlStatusBufferSize,
        xmlStatusMaxConnections,
        xmlScriptsDirectory,
        logLevel,
        kernelEnableDrivers,
        kernelInitialIntegrationLevel,
        kernelDeadlockCheckInterval,
        kernelResourceManagement,
        orderPoolSweepInterval,
        orderPoolSweepAge,
        routerAlgorithm,
        routerEdgeEvaluators,
        routerExplicitDefault,
        routerComputationLimit,
        dispatcherRedispatchInterval,
        dispatcherNewOrderDelay,
        dispatcherOrderPriorities,
        dispatcherVehiclePriorities,
        dispatcherVehicleCandidatePriorities,
        dispatcherOrderCandidatePriorities,
        dispatcherParkIdleVehicles,
        dispatcherRechargeIdleVehicles,
        dispatcherKeepRecharging,
        dispatcherRecoveryThreshold,
        loopbackPlaceUnpositionedVehicles,
        loopbackTimeFactor,
        loopbackOperatingTime,
        loopbackAcceleration,
        loopbackDeceleration,
        loopbackRechargeRate,
        loopbackEnergyDrain,
        loopbackPositionReportInterval,
        overviewVehicleTheme,
        overviewLocationTheme,
    ) + WatchdogSettings.all + Vda5050Settings.all + extensionsDirectory + dataDirectory
}

/** Log levels a user can choose, in SLF4J's names. */
enum class LogLevel { ERROR, WARN, INFO, DEBUG, TRACE }
