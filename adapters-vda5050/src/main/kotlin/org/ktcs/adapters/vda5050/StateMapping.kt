package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.adapters.vda5050.protocol.VehicleError
import org.ktcs.api.model.VehicleState

/** The vehicle state a `state` message means, by openTCS's mapping. */
internal fun State.vehicleState(): VehicleState = when {
    errors.any { it.errorLevel == Vda.FATAL } -> VehicleState.ERROR

    operatingMode != "AUTOMATIC" && operatingMode != "SEMIAUTOMATIC" -> VehicleState.UNAVAILABLE

    batteryState.charging -> VehicleState.CHARGING

    driving || nodeStates.isNotEmpty() || edgeStates.isNotEmpty() ||
        actionStates.any { it.actionStatus != Vda.FINISHED && it.actionStatus != Vda.FAILED } ->
        VehicleState.EXECUTING

    else -> VehicleState.IDLE
}

/** The error types of this [level] (e.g. `FATAL`), joined with " | ", or `null` if there are none. */
internal fun State.errorTypes(level: String): String? =
    errors.filter { it.errorLevel == level }.map { it.errorType }.takeIf { it.isNotEmpty() }?.joinToString(" | ")

/** "LEVEL type: description", as notifications and the panel show an error. */
internal fun VehicleError.described(): String = "$errorLevel $errorType${errorDescription?.let { ": $it" } ?: ""}"
