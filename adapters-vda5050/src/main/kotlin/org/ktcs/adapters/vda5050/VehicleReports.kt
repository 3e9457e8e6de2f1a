package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState

/**
 * What a VDA 5050 vehicle's messages tell the kernel: its position, pose, energy, loads, length, errors and state.
 * A state message repeats most of it every second, and an unchanged value is not worth a kernel task, so only
 * changes are reported; [reset] (when the driver is enabled) reports everything again.
 */
internal class VehicleReports(
    private val vehicleName: String,
    private val context: DriverContext,
    private val properties: Vda5050Properties,
) {
    private var state: VehicleState? = null
    private var energy = -1
    private var errors: Set<String> = emptySet()

    @Volatile private var pose: Triple<Double, Double, Double>? = null // also written by visualization

    fun reset() {
        state = null
        energy = -1
        pose = null
    }

    /** Everything a `state` message says about the vehicle except its state, which depends on the connection. */
    fun fromState(message: State) {
        if (message.lastNodeId.isNotEmpty() && context.plantModel.point(message.lastNodeId) != null &&
            context.vehicle().currentPosition != message.lastNodeId
        ) {
            context.reportPosition(message.lastNodeId)
        }
        message.agvPosition?.let { pose(it.x, it.y, it.theta) }
        val charge = message.batteryState.batteryCharge.toInt().coerceIn(0, 100)
        if (charge != energy) {
            energy = charge
            context.reportEnergyLevel(charge)
        }
        val devices = message.loads.orEmpty().mapIndexed { i, load ->
            LoadHandlingDevice(load.loadPosition?.takeIf { it.isNotEmpty() } ?: "LHD-$i", full = true)
        }
        if (devices != context.vehicle().loadHandlingDevices) context.reportLoadHandlingDevices(devices)
        length(loaded = devices.isNotEmpty())
        properties(message)
    }

    fun state(vehicleState: VehicleState) {
        if (vehicleState == state) return
        state = vehicleState
        context.reportState(vehicleState)
    }

    fun pose(x: Double, y: Double, theta: Double) {
        val reported = Triple(x, y, theta)
        if (reported == pose) return
        pose = reported
        context.reportPrecisePosition(Position((x * MM_PER_M).toLong(), (y * MM_PER_M).toLong()), Math.toDegrees(theta))
    }

    /** openTCS's `vda5050:vehicleLengthLoaded`/`Unloaded`: the vehicle's length follows its load state. */
    private fun length(loaded: Boolean) {
        val length = (if (loaded) properties.vehicleLengthLoaded else properties.vehicleLengthUnloaded) ?: return
        if (context.vehicle().boundingBox.length != length.toLong()) context.reportLength(length.toLong())
    }

    private fun properties(message: State) {
        val described = message.errors.map { it.described() }.toSet()
        (described - errors).filter { it.startsWith(Vda.FATAL) }.forEach {
            context.notifyUser(NotificationLevel.IMPORTANT, "VDA 5050 vehicle $vehicleName reports $it")
        }
        if (described != errors) {
            errors = described
            context.setVehicleProperty("vda5050:errors.fatal", message.errorTypes(Vda.FATAL))
            context.setVehicleProperty("vda5050:errors.warning", message.errorTypes(Vda.WARNING))
        }
        val paused = message.paused?.toString()
        if (context.vehicle().properties["vda5050:paused"] != paused) {
            context.setVehicleProperty("vda5050:paused", paused)
        }
    }

    companion object {
        const val MM_PER_M = 1000.0
    }
}
