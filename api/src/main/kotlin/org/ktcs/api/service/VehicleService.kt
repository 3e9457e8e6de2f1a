package org.ktcs.api.service

import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.DriverPanelView
import org.ktcs.api.event.DriverEvent
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle

/** Reads and changes vehicles and their drivers. Every method may be called from any coroutine. */
public interface VehicleService {
    /** All vehicles, or those in [procState]. */
    public suspend fun vehicles(procState: ProcState? = null): List<Vehicle>

    /** The vehicle named [name], or `null`. */
    public suspend fun vehicle(name: String): Vehicle?

    /** Sets how far the kernel integrates the vehicle (TO_BE_UTILIZED: it gets orders). */
    public suspend fun setIntegrationLevel(vehicle: String, level: IntegrationLevel)

    /** Pauses the vehicle (it is granted no further resources and its driver is told) or resumes it. */
    public suspend fun setPaused(vehicle: String, paused: Boolean)

    /** Sets the order types the vehicle may process. */
    public suspend fun setAllowedOrderTypes(vehicle: String, types: Set<String>)

    /** Sets the order types the vehicle accepts, with priorities. */
    public suspend fun setAcceptableOrderTypes(vehicle: String, types: Set<AcceptableOrderType>)

    /** Sets the vehicle's energy thresholds. */
    public suspend fun setEnergyLevelThresholdSet(vehicle: String, thresholds: EnergyLevelThresholdSet)

    /** Sets the key of the envelopes the vehicle occupies (`null`: none). */
    public suspend fun setEnvelopeKey(vehicle: String, key: String?)

    /** Which drivers could drive the vehicle and which one is attached. */
    public suspend fun driverAttachment(vehicle: String): DriverAttachment

    /** Attaches the driver made by the factory named [driver]; the vehicle must not be processing an order. */
    public suspend fun attachDriver(vehicle: String, driver: String)

    /** Enables or disables the vehicle's driver. */
    public suspend fun setDriverEnabled(vehicle: String, enabled: Boolean)

    /** Passes a message to the vehicle's driver. */
    public suspend fun sendDriverMessage(vehicle: String, message: DriverMessage)

    /**
     * The vehicle's driver, its panel, the driver's state and the vehicle's command queue. Fails with
     * [org.ktcs.api.error.ObjectUnknownException] for an unknown vehicle and
     * [org.ktcs.api.error.IllegalStateChangeException] for a vehicle without a driver.
     */
    public suspend fun driverPanel(vehicle: String): DriverPanelView

    /**
     * Checks [command] with [parameters] against the panel of [driver] and passes it to the vehicle's driver in the
     * kernel context. Fails with [org.ktcs.api.error.ObjectUnknownException] for an unknown vehicle,
     * [org.ktcs.api.error.IllegalStateChangeException] if [driver] does not drive the vehicle, and
     * [org.ktcs.api.error.InvalidRequestException] naming the problem for an unknown command or a bad parameter.
     */
    public suspend fun executeDriverCommand(
        vehicle: String,
        driver: String,
        command: String,
        parameters: Map<String, String>,
    )

    /** The latest events the drivers published (at most a few dozen per vehicle), oldest first; `null`: every vehicle. */
    public suspend fun recentDriverEvents(vehicle: String? = null): List<DriverEvent>
}

/** The drivers available for a vehicle and the one attached (`null`: none), by factory name. */
public data class DriverAttachment(
    val vehicle: String,
    val availableDrivers: List<String>,
    val attachedDriver: String?,
    val driverEnabled: Boolean,
)
