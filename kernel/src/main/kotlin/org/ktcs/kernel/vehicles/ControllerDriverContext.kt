package org.ktcs.kernel.vehicles

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.event.DriverEvent
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState

/**
 * A driver's view of the kernel. Every report is queued into the kernel context, even one made from it: a driver
 * may report from inside a call the kernel made (e.g. a command it completes at once), and the controller must
 * not be re-entered then. Queued reports keep the order they were made in.
 */
class ControllerDriverContext(
    private val controller: VehicleController,
    private val env: VehicleEnvironment,
    private val recentEvents: RecentDriverEvents = RecentDriverEvents(),
) : DriverContext {
    private val vehicleName = controller.name

    override val clock: KernelClock get() = env.context

    // Drivers call these from their own threads: they read what the plant publishes for any thread.
    override val plantModel: PlantModel get() = env.plant.layoutWithLocks()

    override fun vehicle(): Vehicle = env.plant.publishedVehicle(vehicleName)
        ?: throw ObjectUnknownException("vehicle '$vehicleName' is no longer in the plant model")

    override fun vehiclePositions(): Map<String, String> = env.plant.publishedVehicles()
        .mapNotNull { vehicle -> vehicle.currentPosition?.let { vehicle.name to it } }.toMap()

    override fun reportPosition(point: String?) = later {
        if (point != null && env.plant.staticModel().point(point) == null) {
            env.notifications.publish(
                vehicleName,
                NotificationLevel.IMPORTANT,
                "vehicle $vehicleName reported unknown point '$point'",
            )
        } else {
            controller.onPositionReported(point)
        }
    }

    override fun reportPrecisePosition(position: Position?, orientationAngle: Double) = later {
        env.plant.updateVehicle(vehicleName) {
            it.copy(precisePosition = position, orientationAngle = orientationAngle)
        }
    }

    override fun reportState(state: VehicleState) = later {
        val previous = env.plant.vehicle(vehicleName).state
        val vehicle = env.plant.updateVehicle(vehicleName) { it.withState(state, env) }
        if (previous != state && (mayTakeWork(vehicle) || previous == VehicleState.CHARGING)) {
            env.vehicleMayBeAvailable()
        }
    }

    override fun reportEnergyLevel(percent: Int) = later {
        val previous = env.plant.vehicle(vehicleName).energyLevel
        val vehicle = env.plant.updateVehicle(vehicleName) { it.copy(energyLevel = percent.coerceIn(0, 100)) }
        if (previous != percent && mayTakeWork(vehicle)) env.vehicleMayBeAvailable()
    }

    override fun reportLoadHandlingDevices(devices: List<LoadHandlingDevice>) = later {
        val previous = env.plant.vehicle(vehicleName).loadHandlingDevices
        val vehicle = env.plant.updateVehicle(vehicleName) { it.copy(loadHandlingDevices = devices) }
        // An emptied vehicle no longer vetoes orders that load it.
        if (previous != devices && mayTakeWork(vehicle)) env.vehicleMayBeAvailable()
    }

    override fun commandExecuted(command: MovementCommand) = later { controller.onCommandExecuted(command) }

    override fun commandFailed(command: MovementCommand) = later { controller.onCommandFailed(command) }

    override fun commandFailed(command: MovementCommand, reason: String) =
        later { controller.onCommandFailed(command, reason) }

    override fun reportLength(length: Long) = later {
        env.plant.updateVehicle(vehicleName) { it.copy(boundingBox = it.boundingBox.copy(length = length)) }
    }

    override fun setVehicleProperty(key: String, value: String?) = later {
        env.plant.updateVehicle(vehicleName) { it.copy(properties = it.properties.setOrRemove(key, value)) }
    }

    override fun setTransportOrderProperty(key: String, value: String?) = later {
        controller.transportOrder?.let { order ->
            env.orders.update(order) { it.copy(properties = it.properties.setOrRemove(key, value)) }
        }
    }

    override fun publishEvent(type: String, payload: Map<String, String>) = later {
        val event = DriverEvent(vehicleName, type, payload, env.context.now())
        recentEvents.add(event)
        env.events.publish(event)
    }

    override fun notifyUser(level: NotificationLevel, text: String) = later {
        env.notifications.publish(vehicleName, level, text)
    }

    @Volatile
    private var retired = false

    /** Ignores everything the driver reports from now on, e.g. once the plant model was replaced. */
    fun retire() {
        retired = true
    }

    /**
     * Whether a report of [vehicle]'s may change what the dispatcher can give it or says about it: not while it works
     * on an order it may not leave (not dispensable), unless it charges (its energy then decides whether it counts as
     * recharged). Such a vehicle reports its state and energy many times per order, and each dispatcher run reads the
     * whole fleet; it becomes available when its order ends, which runs the dispatcher anyway.
     */
    private fun mayTakeWork(vehicle: Vehicle): Boolean {
        val order = vehicle.transportOrder ?: return true
        return vehicle.state == VehicleState.CHARGING || env.orders.get(order)?.dispensable != false
    }

    // Checked when the task runs: a report queued before retirement must not reach the next plant either.
    private fun later(action: () -> Unit) {
        env.context.execute { if (!retired) action() }
    }

    /** A copy with [key] set to [value], or without [key] if [value] is null (how drivers remove a property). */
    private fun Map<String, String>.setOrRemove(key: String, value: String?): Map<String, String> =
        if (value == null) this - key else this + (key to value)
}
