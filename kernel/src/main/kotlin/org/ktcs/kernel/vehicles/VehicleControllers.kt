package org.ktcs.kernel.vehicles

import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.KernelException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.event.DriverEvent
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.service.DriverAttachment
import org.slf4j.LoggerFactory

/**
 * One controller per vehicle, and the drivers attached to them. A vehicle gets the driver its property
 * `tcs:preferredAdapterClass` names (a factory's name or class name), else the first factory that claims it (e.g. from
 * the vehicle's own properties), else the first factory that can drive it.
 * Confined to the kernel context.
 */
class VehicleControllers(private val env: VehicleEnvironment, private val factories: List<VehicleDriverFactory>) :
    DriverAttachments {
    private val log = LoggerFactory.getLogger(VehicleControllers::class.java)
    private val controllers = LinkedHashMap<String, VehicleController>()
    private val contexts = HashMap<String, ControllerDriverContext>()

    /** The latest events of the drivers, for clients that connect later. */
    val recentEvents = RecentDriverEvents()

    fun controller(vehicle: String): VehicleController =
        controllers[vehicle] ?: throw ObjectUnknownException("unknown vehicle '$vehicle'")

    fun all(): Collection<VehicleController> = controllers.values

    override fun driverName(vehicle: String): String? = controller(vehicle).driverName

    override fun recentDriverEvents(vehicle: String?): List<DriverEvent> = recentEvents.of(vehicle)

    /** Creates the controllers for the vehicles of the plant and attaches their preferred drivers. */
    fun start(enableDrivers: Boolean, integrationLevel: IntegrationLevel) {
        env.events.assertConfined { "VehicleControllers.start" }
        env.plant.vehicles().forEach { vehicle ->
            val controller = VehicleController(vehicle.name, env)
            controllers[vehicle.name] = controller
            contexts[vehicle.name] = ControllerDriverContext(controller, env, recentEvents)
            env.plant.updateVehicle(vehicle.name) { it.copy(integrationLevel = integrationLevel) }
            preferredFactory(vehicle.name)?.let { factory ->
                try {
                    attach(vehicle.name, factory.name)
                    if (enableDrivers) setDriverEnabled(vehicle.name, true)
                } catch (error: KernelException) {
                    // One vehicle with a bad driver setting must not keep the others (or the kernel) from starting.
                    log.warn("vehicle {} starts without a driver: {}", vehicle.name, error.message)
                    env.notifications.publish(
                        vehicle.name,
                        NotificationLevel.IMPORTANT,
                        "vehicle ${vehicle.name} has no driver: ${error.message}",
                    )
                }
            }
        }
        log.info(
            "vehicles={} drivers={}",
            controllers.size,
            controllers.values.joinToString {
                "${it.name}:${it.driverName ?: "none"}"
            },
        )
    }

    fun stop() {
        controllers.values.forEach { it.driver?.disable() }
    }

    /** Disables every driver and forgets every controller, before the plant model is replaced. */
    fun discard() {
        env.events.assertConfined { "VehicleControllers.discard" }
        stop()
        contexts.values.forEach(ControllerDriverContext::retire)
        controllers.clear()
        contexts.clear()
        recentEvents.clear()
    }

    override fun attachment(vehicle: String): DriverAttachment {
        val controller = controller(vehicle)
        return DriverAttachment(
            vehicle,
            available(vehicle).map { it.name },
            controller.driverName,
            controller.driver?.isEnabled == true,
        )
    }

    fun attach(vehicle: String, driverName: String) {
        env.events.assertConfined { "VehicleControllers.attach" }
        val controller = controller(vehicle)
        val factory = available(vehicle).firstOrNull { it.name == driverName }
            ?: throw InvalidRequestException(
                "no driver '$driverName' for vehicle '$vehicle'; available: ${available(vehicle).joinToString {
                    it.name
                }.ifEmpty { "none" }}",
            )
        if (controller.transportOrder != null) {
            throw IllegalStateChangeException(
                "vehicle '$vehicle' is processing order '${controller.transportOrder}'",
            )
        }
        val driver = try {
            factory.create(vehicle, contexts.getValue(vehicle))
        } catch (error: IllegalArgumentException) {
            throw InvalidRequestException("driver '${factory.name}' cannot drive vehicle '$vehicle': ${error.message}")
        }
        controller.attach(factory.name, driver)
    }

    fun setDriverEnabled(vehicle: String, enabled: Boolean) {
        env.events.assertConfined { "VehicleControllers.setDriverEnabled" }
        val controller = controller(vehicle)
        val driver = controller.driver ?: throw IllegalStateChangeException("vehicle '$vehicle' has no driver attached")
        if (enabled) {
            driver.enable()
            controller.onDriverReady()
        } else {
            if (controller.transportOrder != null) controller.withdraw(immediate = true)
            driver.disable()
        }
    }

    fun sendMessage(vehicle: String, message: DriverMessage) {
        env.events.assertConfined { "VehicleControllers.sendMessage" }
        val driver =
            controller(vehicle).driver ?: throw IllegalStateChangeException("vehicle '$vehicle' has no driver attached")
        try {
            driver.processMessage(message)
        } catch (error: IllegalArgumentException) {
            throw InvalidRequestException("the driver of vehicle '$vehicle' refused the message: ${error.message}")
        }
    }

    fun setIntegrationLevel(vehicle: String, level: IntegrationLevel) {
        env.events.assertConfined { "VehicleControllers.setIntegrationLevel" }
        val controller = controller(vehicle)
        if (level <= IntegrationLevel.TO_BE_NOTICED && controller.transportOrder != null) {
            throw IllegalStateChangeException(
                "vehicle '$vehicle' is processing order '${controller.transportOrder}'; withdraw it before setting $level",
            )
        }
        if (level >= IntegrationLevel.TO_BE_RESPECTED && controller.transportOrder == null) {
            controller.positionHolders().takeIf { it.isNotEmpty() }?.let { holders ->
                val text = controller.positionTakenText(holders, level)
                env.notifications.publish(vehicle, NotificationLevel.IMPORTANT, text)
                throw IllegalStateChangeException(text)
            }
        }
        env.plant.updateVehicle(vehicle) { it.copy(integrationLevel = level) }
        // A vehicle on its way keeps what it was granted; its position is settled when its order ends.
        if (controller.transportOrder == null) controller.occupyPosition(level)
        env.vehicleMayBeAvailable()
    }

    fun setPaused(vehicle: String, paused: Boolean) {
        env.events.assertConfined { "VehicleControllers.setPaused" }
        val controller = controller(vehicle)
        env.plant.updateVehicle(vehicle) { it.copy(paused = paused) }
        env.scheduler().setPaused(controller, paused)
        controller.driver?.onPaused(paused)
        if (!paused) env.vehicleMayBeAvailable()
    }

    /** The factory named [name], or `null`. */
    override fun factory(name: String): VehicleDriverFactory? = factories.firstOrNull { it.name == name }

    private fun available(vehicle: String): List<VehicleDriverFactory> =
        factories.filter { it.canDrive(vehicle, contexts.getValue(vehicle)) }

    private fun preferredFactory(vehicle: String): VehicleDriverFactory? {
        val preferred = env.plant.vehicle(vehicle).properties[PREFERRED_DRIVER]
        val candidates = available(vehicle)
        return candidates.firstOrNull { preferred != null && (it.name == preferred || it.javaClass.name == preferred) }
            ?: candidates.firstOrNull { it.claims(vehicle, contexts.getValue(vehicle)) }
            ?: candidates.firstOrNull()
    }

    companion object {
        const val PREFERRED_DRIVER = "tcs:preferredAdapterClass"
    }
}
