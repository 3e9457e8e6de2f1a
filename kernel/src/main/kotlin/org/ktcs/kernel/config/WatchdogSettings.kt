package org.ktcs.kernel.config

import org.ktcs.extension.config.Setting
import org.ktcs.extension.config.booleanSetting
import org.ktcs.extension.config.longSetting

/** openTCS's operations watchdogs (`watchdog.*`), each a user notification. Listed in [KtcsSettings.all]. */
object WatchdogSettings {
    private val MILLIS_PER_DAY = 0L..86_400_000L

    val strandedVehicleCheckInterval = longSetting(
        "watchdog.strandedVehicleCheckInterval",
        10_000,
        MILLIS_PER_DAY,
        "Milliseconds between checks for stranded vehicles (0: never).",
    )
    val strandedVehicleDuration = longSetting(
        "watchdog.strandedVehicleDurationThreshold",
        60_000,
        MILLIS_PER_DAY,
        "How long an idle vehicle may stand off a park position without an order (or hold an order without moving) " +
            "before a notification says it is stranded.",
    )
    val transportOrderCheckInterval = longSetting(
        "watchdog.transportOrderCheckInterval",
        10_000,
        MILLIS_PER_DAY,
        "Milliseconds between checks for orders waiting too long or past their deadline (0: never).",
    )
    val idleTransportOrderDuration = longSetting(
        "watchdog.idleTransportOrderDurationThreshold",
        60_000,
        MILLIS_PER_DAY,
        "How long an order may wait unassigned before a notification says so, with its reason.",
    )
    val positionOffRoute = booleanSetting(
        "watchdog.reportPositionOffRoute",
        true,
        "Notify when a vehicle reports a position that is not on the route it was sent.",
    )

    val all: List<Setting<*>> = listOf(
        strandedVehicleCheckInterval,
        strandedVehicleDuration,
        transportOrderCheckInterval,
        idleTransportOrderDuration,
        positionOffRoute,
    )
}
