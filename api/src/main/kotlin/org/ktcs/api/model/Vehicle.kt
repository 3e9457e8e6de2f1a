package org.ktcs.api.model

import java.time.Instant

/**
 * A vehicle: how the plant model describes it, and what the kernel knows about it while it runs.
 *
 * The plant-model file stores the fields up to [properties]; everything after them is runtime state that starts at
 * its default when a model is loaded.
 *
 * @property maxVelocity mm/s forward.
 * @property maxReverseVelocity mm/s backward.
 * @property envelopeKey selects which envelopes of points and paths this vehicle occupies; `null` for none.
 * @property energyLevel percent.
 * @property stateTimestamp when [state] last changed.
 * @property procStateTimestamp when [procState] last changed; the dispatcher's idle delays count from here.
 * @property currentPosition name of the point the vehicle reported last, `null` if unknown.
 * @property precisePosition the exact position the vehicle reported, `null` if unknown.
 * @property orientationAngle degrees, `NaN` when unknown.
 * @property transportOrder name of the order the vehicle processes, if any.
 * @property orderSequence name of the order sequence the vehicle processes, if any.
 * @property allocatedResources resources (points, paths, locations) the scheduler gave the vehicle, per movement step.
 * @property claimedResources resources the vehicle will need for the rest of its route, per movement step.
 * @property waitingReason why the idle vehicle took no order in the dispatcher's last run (kTCS only), `null` if it took one or no order waits.
 */
public data class Vehicle(
    override val name: String,
    val energyLevelThresholdSet: EnergyLevelThresholdSet = EnergyLevelThresholdSet(),
    val maxVelocity: Int = 1000,
    val maxReverseVelocity: Int = 1000,
    val boundingBox: BoundingBox = BoundingBox(),
    val envelopeKey: String? = null,
    val layout: VehicleLayout = VehicleLayout(),
    override val properties: Map<String, String> = emptyMap(),
    val energyLevel: Int = 100,
    val state: VehicleState = VehicleState.UNKNOWN,
    val stateTimestamp: Instant = Instant.EPOCH,
    val procState: ProcState = ProcState.IDLE,
    val procStateTimestamp: Instant = Instant.EPOCH,
    val integrationLevel: IntegrationLevel = IntegrationLevel.TO_BE_RESPECTED,
    val paused: Boolean = false,
    val currentPosition: String? = null,
    val precisePosition: Position? = null,
    val orientationAngle: Double = Double.NaN,
    val transportOrder: String? = null,
    val orderSequence: String? = null,
    val allocatedResources: List<Set<String>> = emptyList(),
    val claimedResources: List<Set<String>> = emptyList(),
    val allowedOrderTypes: Set<String> = setOf(ANY_ORDER_TYPE),
    val acceptableOrderTypes: Set<AcceptableOrderType> = setOf(AcceptableOrderType(ANY_ORDER_TYPE, 0)),
    val loadHandlingDevices: List<LoadHandlingDevice> = emptyList(),
    val rechargeOperation: String = DEFAULT_RECHARGE_OPERATION,
    val waitingReason: String? = null,
) : PlantObject {
    public companion object {
        /** The order type that matches every order type. */
        public const val ANY_ORDER_TYPE: String = "*"

        /** The operation that recharges a vehicle unless its driver says otherwise. */
        public const val DEFAULT_RECHARGE_OPERATION: String = "CHARGE"
    }
}

/**
 * Energy levels, in percent, that drive recharging decisions.
 *
 * @property critical below this the vehicle must recharge and takes no orders.
 * @property good above this the vehicle needs no recharge.
 * @property sufficientlyRecharged a charging vehicle may take orders again from this level.
 * @property fullyRecharged charging stops at this level.
 */
public data class EnergyLevelThresholdSet(
    val critical: Int = 30,
    val good: Int = 90,
    val sufficientlyRecharged: Int = 30,
    val fullyRecharged: Int = 90,
)

/** How a vehicle is drawn; [routeColor] is `#RRGGBB`. */
public data class VehicleLayout(val routeColor: String = "#00FF00")

/** What a vehicle reports about itself, as openTCS names it. */
public enum class VehicleState { UNKNOWN, UNAVAILABLE, ERROR, IDLE, EXECUTING, CHARGING }

/** Where a vehicle is in processing orders. */
public enum class ProcState { IDLE, AWAITING_ORDER, PROCESSING_ORDER }

/** How far the kernel integrates a vehicle into its work. */
public enum class IntegrationLevel {
    /** Not shown and not considered at all. */
    TO_BE_IGNORED,

    /** Its position is shown, but it takes no resources and gets no orders. */
    TO_BE_NOTICED,

    /** Its position and resources are respected, but it gets no orders. */
    TO_BE_RESPECTED,

    /** Fully part of the fleet: it gets orders. */
    TO_BE_UTILIZED,
}

/** An order type a vehicle accepts, with its priority (lower is preferred). */
public data class AcceptableOrderType(val name: String, val priority: Int)

/** A load handling device of a vehicle (a fork, a conveyor) and whether it carries a load. */
public data class LoadHandlingDevice(val label: String, val full: Boolean)
