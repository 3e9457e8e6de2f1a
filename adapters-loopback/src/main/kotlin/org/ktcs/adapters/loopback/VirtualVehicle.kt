package org.ktcs.adapters.loopback

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState

/** What the simulated vehicle looks like; every change is reported to the kernel through [context]. */
internal class VirtualVehicle(private val context: DriverContext) {
    val battery = Battery(context::reportEnergyLevel)

    var position: String? = null
        private set
    var precisePosition: Position? = null
        private set
    var orientation: Double = Double.NaN
        private set
    var state: VehicleState = VehicleState.UNKNOWN
        private set
    var loaded: Boolean = false
        private set

    fun reportPoint(point: String?) {
        position = point
        context.reportPosition(point)
    }

    /** Reports the vehicle at [position] facing [angle]; a `NaN` angle keeps the current orientation. */
    fun place(position: Position?, angle: Double = Double.NaN) {
        precisePosition = position
        if (!angle.isNaN()) orientation = angle
        context.reportPrecisePosition(position, orientation)
    }

    /** Sets the orientation, `NaN` for unknown. */
    fun turn(angle: Double) {
        orientation = angle
        context.reportPrecisePosition(precisePosition, angle)
    }

    fun changeState(newState: VehicleState) {
        if (newState == state) return
        state = newState
        context.reportState(newState)
    }

    fun setLoaded(full: Boolean) {
        val changed = full != loaded
        loaded = full
        context.reportLoadHandlingDevices(listOf(LoadHandlingDevice(LOAD_HANDLING_DEVICE, full)))
        if (changed) context.publishEvent(LoopbackEvents.LOAD_CHANGED, mapOf("loaded" to full.toString()))
    }

    companion object {
        /** The label of the one load handling device, as in openTCS. */
        const val LOAD_HANDLING_DEVICE: String = "default"
    }
}
