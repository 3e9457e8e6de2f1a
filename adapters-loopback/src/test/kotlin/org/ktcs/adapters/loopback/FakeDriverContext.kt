package org.ktcs.adapters.loopback

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState

/** Everything a driver reported, with the virtual time it happened at. */
sealed interface Report {
    data class PositionReport(val point: String?) : Report

    data class PrecisePosition(val position: Position?, val angle: Double) : Report

    data class State(val state: VehicleState) : Report

    data class Energy(val percent: Int) : Report

    data class Devices(val devices: List<LoadHandlingDevice>) : Report

    data class Executed(val command: MovementCommand) : Report

    data class Failed(val command: MovementCommand) : Report

    data class OrderProperty(val key: String, val value: String?) : Report

    data class Event(val type: String, val payload: Map<String, String>) : Report

    data class Notification(val level: NotificationLevel, val text: String) : Report
}

/** A driver context that records every report and, like the kernel, applies it to its copy of the vehicle. */
class FakeDriverContext(
    override var plantModel: PlantModel,
    vehicleName: String,
    override val clock: VirtualClock = VirtualClock(),
) : DriverContext {
    private var vehicle: Vehicle = requireNotNull(plantModel.vehicle(vehicleName)) { "no vehicle $vehicleName" }

    /** Reports in the order they were made, each with the virtual time. */
    val timeline = mutableListOf<Pair<Long, Report>>()

    val reports: List<Report> get() = timeline.map { it.second }

    inline fun <reified R : Report> reportsOf(): List<R> = reports.filterIsInstance<R>()

    inline fun <reified R : Report> timesOf(): List<Long> = timeline.filter { it.second is R }.map { it.first }

    /** Runs after a command was reported executed, e.g. to send the next one the way a kernel might. */
    var afterExecuted: (MovementCommand) -> Unit = {}

    fun updateVehicle(change: (Vehicle) -> Vehicle) {
        vehicle = change(vehicle)
    }

    override fun vehicle(): Vehicle = vehicle

    /** Where the other vehicles stand, as a test sets it. */
    var otherPositions: Map<String, String> = emptyMap()

    override fun vehiclePositions(): Map<String, String> =
        otherPositions + listOfNotNull(vehicle.currentPosition?.let { vehicle.name to it })

    override fun reportPosition(point: String?) = record(Report.PositionReport(point)) { copy(currentPosition = point) }

    override fun reportPrecisePosition(position: Position?, orientationAngle: Double) =
        record(Report.PrecisePosition(position, orientationAngle)) {
            copy(precisePosition = position, orientationAngle = orientationAngle)
        }

    override fun reportState(state: VehicleState) = record(Report.State(state)) { copy(state = state) }

    override fun reportEnergyLevel(percent: Int) = record(Report.Energy(percent)) { copy(energyLevel = percent) }

    override fun reportLoadHandlingDevices(devices: List<LoadHandlingDevice>) =
        record(Report.Devices(devices)) { copy(loadHandlingDevices = devices) }

    override fun commandExecuted(command: MovementCommand) {
        record(Report.Executed(command))
        afterExecuted(command)
    }

    override fun commandFailed(command: MovementCommand) = record(Report.Failed(command))

    override fun reportLength(length: Long) = updateVehicle {
        it.copy(boundingBox = it.boundingBox.copy(length = length))
    }

    override fun setVehicleProperty(key: String, value: String?) = updateVehicle {
        it.copy(properties = if (value == null) it.properties - key else it.properties + (key to value))
    }

    override fun setTransportOrderProperty(key: String, value: String?) = record(Report.OrderProperty(key, value))

    override fun publishEvent(type: String, payload: Map<String, String>) = record(Report.Event(type, payload))

    override fun notifyUser(level: NotificationLevel, text: String) = record(Report.Notification(level, text))

    private fun record(report: Report, apply: Vehicle.() -> Vehicle = { this }) {
        timeline += clock.nowMillis to report
        vehicle = vehicle.apply()
    }
}
