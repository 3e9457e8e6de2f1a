package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState
import java.util.concurrent.atomic.AtomicReference

/**
 * What a VDA 5050 vehicle's messages tell the kernel: its position, pose, energy, loads, length, errors and state.
 * A state message repeats most of it every second, and an unchanged value is not worth a kernel task, so only
 * changes are reported; [reset] (when the driver is enabled) reports everything again. Poses (from `state` and
 * `visualization`) are coalesced: however many arrive while one waits for the kernel, the kernel reports the latest;
 * a pose that matches the last one taken at what the kernel shows (millimetres, a tenth of a degree) costs no kernel
 * task at all, so a vehicle standing still (or a localisation jittering below that) keeps the kernel thread idle.
 */
internal class VehicleReports(
    private val vehicleName: String,
    private val context: DriverContext,
    private val properties: Vda5050Properties,
) {
    private var state: VehicleState? = null
    private var energy = -1
    private var errors: Set<String> = emptySet()

    private var pose: Pose? = null
    private val pendingPose = AtomicReference<Pose?>()

    // The last pose handed towards the kernel, on the link's threads (guarded by this).
    private var lastTaken: Pose? = null

    fun reset() {
        state = null
        energy = -1
        pose = null
        synchronized(this) { lastTaken = null }
    }

    /** Everything a `state` message says about the vehicle except its state, which depends on the connection. */
    fun fromState(message: State) {
        if (message.lastNodeId.isNotEmpty() && context.plantModel.point(message.lastNodeId) != null &&
            context.vehicle().currentPosition != message.lastNodeId
        ) {
            context.reportPosition(message.lastNodeId)
        }
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

    /** The vehicle's pose (metres, radians) from a message that just arrived, on the link's thread. */
    @Synchronized
    fun pose(x: Double, y: Double, theta: Double) {
        val next = Pose.of(x, y, theta)
        if (next == lastTaken) return
        lastTaken = next
        if (pendingPose.getAndSet(next) == null) context.clock.schedule(0, ::reportPose)
    }

    private fun reportPose() {
        val latest = pendingPose.getAndSet(null) ?: return
        if (latest == pose) return
        pose = latest
        context.reportPrecisePosition(Position(latest.xMillimetres, latest.yMillimetres), latest.degrees)
    }

    /** A pose at the resolution the kernel reports it: millimetres and a tenth of a degree. */
    private data class Pose(val xMillimetres: Long, val yMillimetres: Long, val degrees: Double) {
        companion object {
            fun of(x: Double, y: Double, theta: Double) = Pose(
                (x * MM_PER_M).toLong(),
                (y * MM_PER_M).toLong(),
                Math.round(Math.toDegrees(theta) * TENTHS) / TENTHS,
            )
        }
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
        private const val TENTHS = 10.0
    }
}
