package org.ktcs.kernel.routing

import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Operations
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder
import java.time.Instant

/** The location type of [station]s: vehicles may load and unload there. */
val transferType = LocationType("Transfer", allowedOperations = setOf("LOAD", "UNLOAD"))

/** A path from [from] to [to], named `from --- to`, drivable forward only unless the velocities say otherwise. */
fun path(
    from: String,
    to: String,
    length: Long = 1000,
    maxVelocity: Int = 1000,
    maxReverseVelocity: Int = 0,
    locked: Boolean = false,
    properties: Map<String, String> = emptyMap(),
) = Path("$from --- $to", from, to, length, maxVelocity, maxReverseVelocity, locked = locked, properties = properties)

/** A plant of [paths] whose points are those the paths name plus [extraPoints]; locations are of [transferType]. */
fun plant(
    vararg paths: Path,
    extraPoints: List<Point> = emptyList(),
    locations: List<Location> = emptyList(),
): PlantModel {
    val named = paths.flatMap { listOf(it.sourcePoint, it.destinationPoint) }.distinct().map(::Point)
    val points = (extraPoints + named).distinctBy { it.name }
    return PlantModel("test", points, paths.toList(), locationTypes = listOf(transferType), locations = locations)
}

/** A location of [transferType] linked to [links]. */
fun station(name: String, vararg links: Link) = Location(name, transferType.name, links = links.toList())

fun vehicle(
    routingGroup: String? = null,
    maxVelocity: Int = 1000,
    maxReverseVelocity: Int = 1000,
    boundingBox: BoundingBox = BoundingBox(),
) = Vehicle(
    name = "Vehicle-01",
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    boundingBox = boundingBox,
    properties = routingGroup?.let { mapOf(ROUTING_GROUP_PROPERTY to it) }.orEmpty(),
)

fun moveTo(point: String) = Destination(point, Operations.MOVE)

/** A transport order visiting [destinations] in turn, avoiding [resourcesToAvoid] if given. */
fun order(vararg destinations: Destination, resourcesToAvoid: String? = null) = TransportOrder(
    name = "TOrder-01",
    driveOrders = destinations.mapIndexed { index, destination -> DriveOrder("Drive-$index", destination) },
    creationTime = Instant.EPOCH,
    properties = resourcesToAvoid?.let { mapOf(RESOURCES_TO_AVOID_PROPERTY to it) }.orEmpty(),
)

fun routerFor(model: PlantModel, configuration: RouterConfiguration = RouterConfiguration()) =
    DefaultRouter(configuration).apply { updateTopology(model) }

fun DefaultRouter.route(from: String, to: String, vehicle: Vehicle = vehicle()): Route? =
    routes(vehicle, from, to).singleOrNull()

/** The points a route visits, from its first step's source on. */
val Route.points: List<String> get() = listOfNotNull(steps.first().sourcePoint) + steps.map { it.destinationPoint }

val Route.paths: List<String?> get() = steps.map { it.path }
