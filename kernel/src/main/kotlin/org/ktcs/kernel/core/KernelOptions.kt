package org.ktcs.kernel.core

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.kernel.vehicles.ResourceManagement

/** The kernel's own settings, as plain values (mapped from the configuration in the Koin module). */
data class KernelOptions(
    /** What a vehicle keeps behind it (openTCS: kernelapp.vehicleResourceManagementType). */
    val resourceManagement: ResourceManagement = ResourceManagement.LENGTH_RESPECTED,
    /** Enable every vehicle's driver at start-up (openTCS: kernelapp.autoEnableDriversOnStartup). */
    val enableDriversOnStart: Boolean = true,
    /** The integration level vehicles start with; TO_BE_UTILIZED lets them take orders at once. */
    val initialIntegrationLevel: IntegrationLevel = IntegrationLevel.TO_BE_UTILIZED,
    /** The dispatcher's safety-net period; it runs on events anyway (openTCS: idleVehicleRedispatchingInterval). */
    val redispatchIntervalMillis: Long = 10_000,
    /** How long a run waits after a new order became dispatchable (`dispatcher.newOrderDelay`; 0 here, at once). */
    val newOrderDispatchDelayMillis: Long = 0,
    /** Mark orders whose destinations no vehicle can connect UNROUTABLE at once. */
    val dismissUnroutableOrders: Boolean = true,
    /** How often final orders are swept out (openTCS: orderpool.sweepInterval). */
    val sweepIntervalMillis: Long = 60_000,
    /** How old a final order must be to be swept out (openTCS: orderpool.sweepAge). */
    val sweepAgeMillis: Long = 86_400_000,
    /** How often the deadlock watchdog looks for vehicles waiting for each other in a cycle, in vehicle time. */
    val deadlockCheckIntervalMillis: Long = 1_000,
    /**
     * How many times faster than the kernel clock the vehicles move: the loopback's `loopback.timeFactor` in a
     * simulation, 1 with real vehicles. Traffic control's timers (the watchdog period, patience) run in vehicle time.
     */
    val vehicleTimeFactor: Double = 1.0,
    /** openTCS's watchdog checks (stranded vehicles, waiting and late orders, positions off route). */
    val watchdog: WatchdogOptions = WatchdogOptions(),
)

/** When [OperationsWatchdog] speaks up; an interval of 0 switches its check off. */
data class WatchdogOptions(
    val strandedVehicleCheckIntervalMillis: Long = 10_000,
    val strandedVehicleMillis: Long = 60_000,
    val orderCheckIntervalMillis: Long = 10_000,
    val idleOrderMillis: Long = 60_000,
    val reportPositionOffRoute: Boolean = true,
)
