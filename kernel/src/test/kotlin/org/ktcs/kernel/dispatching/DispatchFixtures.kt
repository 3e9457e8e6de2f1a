package org.ktcs.kernel.dispatching

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Operations
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import java.time.Instant

/** The time the fake clock starts at. */
val T0: Instant = FakeClock().now

val chargingType = LocationType("Charging", allowedOperations = setOf(Vehicle.DEFAULT_RECHARGE_OPERATION))
val transferType = LocationType("Transfer", allowedOperations = setOf("LOAD", "UNLOAD"))

/**
 * Points named [names] in a row, neighbours joined by a path of 1000 mm drivable both ways. Points in [park] are park
 * positions, with a `tcs:parkingPositionPriority` from [priorities] if given.
 */
fun line(
    vararg names: String,
    park: Set<String> = emptySet(),
    priorities: Map<String, Int> = emptyMap(),
    locations: List<Location> = emptyList(),
): PlantModel {
    val points = names.map { name ->
        Point(
            name,
            type = if (name in park) PointType.PARK_POSITION else PointType.HALT_POSITION,
            properties = priorities[name]?.let {
                mapOf(DispatcherProperties.PARKING_POSITION_PRIORITY to "$it")
            }.orEmpty(),
        )
    }
    val paths = names.toList().zipWithNext { a, b -> Path("$a --- $b", a, b, length = 1000, maxReverseVelocity = 1000) }
    return PlantModel("test", points, paths, locationTypes = listOf(chargingType, transferType), locations = locations)
}

/** The default plant: A…H in a row, stations S1 at C and S2 at F. */
fun plant(vararg extra: Location, park: Set<String> = emptySet(), priorities: Map<String, Int> = emptyMap()) = line(
    "A", "B", "C", "D", "E", "F", "G", "H",
    park = park,
    priorities = priorities,
    locations = listOf(station("S1", "C"), station("S2", "F")) + extra,
)

fun station(name: String, vararg links: String, locked: Boolean = false) =
    Location(name, transferType.name, links = links.map { Link(it) }, locked = locked)

fun charger(name: String, vararg links: String, locked: Boolean = false) =
    Location(name, chargingType.name, links = links.map { Link(it) }, locked = locked)

/** A vehicle ready for orders: utilized, idle, at [at]. */
fun vehicle(
    name: String,
    at: String? = "A",
    energy: Int = 100,
    state: VehicleState = VehicleState.IDLE,
    properties: Map<String, String> = emptyMap(),
) = Vehicle(
    name,
    properties = properties,
    energyLevel = energy,
    state = state,
    procState = ProcState.IDLE,
    procStateTimestamp = T0,
    integrationLevel = IntegrationLevel.TO_BE_UTILIZED,
    currentPosition = at,
)

/** A vehicle busy with [order]. */
fun Vehicle.processing(order: String, state: VehicleState = VehicleState.EXECUTING) =
    copy(transportOrder = order, procState = ProcState.PROCESSING_ORDER, state = state)

fun order(
    name: String,
    vararg destinations: Destination = arrayOf(Destination("S2", "LOAD")),
    type: String = TransportOrder.DEFAULT_TYPE,
    created: Instant = T0,
    deadline: Instant = Instant.MAX,
    intended: String? = null,
    dispensable: Boolean = false,
    sequence: String? = null,
    state: TransportOrderState = TransportOrderState.DISPATCHABLE,
) = TransportOrder(
    name = name,
    driveOrders = destinations.mapIndexed { index, destination -> DriveOrder("Drive-$index", destination) },
    type = type,
    state = state,
    creationTime = created,
    deadline = deadline,
    intendedVehicle = intended,
    wrappingSequence = sequence,
    dispensable = dispensable,
)

fun moveTo(point: String) = Destination(point, Operations.MOVE)

fun load(location: String) = Destination(location, "LOAD")

/** Assignment only: no parking, no recharging. */
val assignOnly = DispatcherConfiguration(parkIdleVehicles = false, rechargeIdleVehicles = false)

fun FakeDispatchContext.dispatch(configuration: DispatcherConfiguration = assignOnly) =
    DefaultDispatcher(configuration, this, DefaultRecoveryEvaluator()).dispatch()

fun FakeDispatchContext.dispatcher(configuration: DispatcherConfiguration = assignOnly) =
    DefaultDispatcher(configuration, this, DefaultRecoveryEvaluator())
