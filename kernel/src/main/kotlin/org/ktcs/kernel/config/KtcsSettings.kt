package org.ktcs.kernel.config

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.extension.config.Setting
import org.ktcs.extension.config.booleanSetting
import org.ktcs.extension.config.doubleSetting
import org.ktcs.extension.config.enumListSetting
import org.ktcs.extension.config.enumSetting
import org.ktcs.extension.config.intSetting
import org.ktcs.extension.config.longSetting
import org.ktcs.extension.config.stringSetting
import org.ktcs.kernel.dispatching.CandidatePriority
import org.ktcs.kernel.dispatching.DEFAULT_ORDER_CANDIDATE_WINDOW
import org.ktcs.kernel.dispatching.OrderPriority
import org.ktcs.kernel.dispatching.VehiclePriority
import org.ktcs.kernel.routing.EdgeEvaluator
import org.ktcs.kernel.routing.RouterConfiguration
import org.ktcs.kernel.routing.RoutingAlgorithm
import org.ktcs.kernel.vehicles.ResourceManagement

/**
 * Every setting of kTCS itself. Extensions declare theirs in [org.ktcs.extension.KtcsExtension.settings]; a key that
 * neither lists is rejected wherever it appears (see [SettingsCatalogue]).
 */
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
    val webEngine = enumSetting(
        "web.engine",
        WebEngine.NETTY,
        "HTTP engine of the web API: NETTY or CIO (Ktor's own). HTTPS (web.tls.*) always runs on Netty.",
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
        "Milliseconds of vehicle time (kernel time times loopback.timeFactor for simulated vehicles) between checks " +
            "for vehicles waiting for each other in a cycle; a deadlock is reported and broken by rerouting (0: off).",
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
    val routerOperationPointSurcharge = intSetting(
        "router.operationPointSurcharge",
        RouterConfiguration.DEFAULT_OPERATION_POINT_SURCHARGE,
        0..100_000,
        "Percent added to the cost of driving onto a point linked to a location, where vehicles stop to operate " +
            "and hold up those behind (0: off).",
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
        listOf(CandidatePriority.BY_DEADLINE, CandidatePriority.BY_INITIAL_ROUTING_COSTS),
        "How a vehicle picks among orders: the same keys as dispatcher.vehicleCandidatePriorities. openTCS's " +
            "default is BY_DEADLINE alone (the oldest order, however far); the nearest within " +
            "dispatcher.orderCandidateWindow cuts the fleet's empty driving to a third (issue #11's grids: 36% of " +
            "vehicle time to 19% with a window of 10, 10-14% with 50).",
    )
    val dispatcherOrderCandidateWindow = intSetting(
        "dispatcher.orderCandidateWindow",
        DEFAULT_ORDER_CANDIDATE_WINDOW,
        0..100_000,
        "How many orders a vehicle picks among: the most urgent by dispatcher.orderPriorities it may take (0: all). " +
            "An order passed over this many times is taken next by a vehicle that can. 10 before session 31; 50 took " +
            "issue #11's grids from 1.73-2.06x the lower bound to 1.52-1.86x in virtual time (seeds 1-4).",
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
        webEngine,
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
        routerOperationPointSurcharge,
        dispatcherRedispatchInterval,
        dispatcherNewOrderDelay,
        dispatcherOrderPriorities,
        dispatcherVehiclePriorities,
        dispatcherVehicleCandidatePriorities,
        dispatcherOrderCandidatePriorities,
        dispatcherOrderCandidateWindow,
        dispatcherParkIdleVehicles,
        dispatcherRechargeIdleVehicles,
        dispatcherKeepRecharging,
        dispatcherRecoveryThreshold,
    ) + WatchdogSettings.all + extensionsDirectory + dataDirectory + PersistenceSettings.all
}

/** The HTTP engine of the web API (`web.engine`). */
enum class WebEngine { NETTY, CIO }

/** Log levels a user can choose, in SLF4J's names. */
enum class LogLevel { ERROR, WARN, INFO, DEBUG, TRACE }

// Durable state (#18): where the kernel's state is stored, how durably, how it comes back, and the log file.
object PersistenceSettings {
    val durability = enumSetting(
        "persistence.durability",
        Durability.COMMIT,
        "When a change counts as stored: COMMIT answers a client's order only once it is committed (survives a " +
            "crash); ASYNC answers at once and commits within milliseconds (a crash may lose the last changes); OFF " +
            "stores nothing (tests and benchmarks; a restart starts empty).",
    )
    val url = Setting(
        "persistence.url",
        "",
        "JDBC URL of the state store, e.g. jdbc:postgresql://db.example.com/ktcs (empty: the embedded SQLite file " +
            "state.db in kernel.dataDirectory).",
        { it },
    )
    val username = Setting("persistence.username", "", "User name for persistence.url (PostgreSQL).", { it })
    val password = Setting("persistence.password", "", "Password for persistence.url (PostgreSQL).", { it })
    val recovery = enumSetting(
        "persistence.recovery",
        RecoveryMode.CONTINUE,
        "What happens at start to orders that were BEING_PROCESSED when kTCS stopped: CONTINUE re-places each " +
            "vehicle at its last known position and reroutes it to its remaining destinations; WITHDRAW withdraws " +
            "them (their history says the kernel restarted).",
    )
    val groupWait = intSetting(
        "persistence.groupWait",
        0,
        0..100_000,
        "Microseconds a flushed commit (COMMIT) may wait for the requests the store's writer expects back (those " +
            "its last commit answered and those already waiting), so that one fsync answers more of them (0: commit " +
            "as soon as the previous commit is on the disk). Pays on a disk whose fsync takes milliseconds; on a " +
            "fast one it costs rate (README, durable state). A lone client never waits.",
    )
    val logFileMaxSize = longSetting(
        "log.file.maxSize",
        50,
        1L..100_000L,
        "MB a log file (kernel.dataDirectory/logs/ktcs.log) grows to before it rolls over; it also rolls daily.",
    )
    val logFileMaxHistory = intSetting(
        "log.file.maxHistory",
        30,
        0..3650,
        "Days of rolled-over log files kept (0: log to the console only, no file).",
    )
    val logFileTotalSizeCap = longSetting(
        "log.file.totalSizeCap",
        1000,
        1L..1_000_000L,
        "MB all log files together may take; the oldest are deleted beyond it.",
    )

    val all: List<Setting<*>> =
        listOf(
            durability,
            url,
            username,
            password,
            recovery,
            groupWait,
            logFileMaxSize,
            logFileMaxHistory,
            logFileTotalSizeCap,
        )
}

/** When a change counts as stored (`persistence.durability`). */
enum class Durability { COMMIT, ASYNC, OFF }

/** What happens at start to orders a vehicle was processing (`persistence.recovery`). */
enum class RecoveryMode { CONTINUE, WITHDRAW }
