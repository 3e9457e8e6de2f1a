package org.ktcs.kernel.persistence.v004

import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.ExecutionTrigger
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.LocationTypeLayout
import org.ktcs.api.model.Path
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PeripheralOperation
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.persistence.ReadWarnings
import org.ktcs.kernel.persistence.toMap
import org.ktcs.kernel.persistence.v7.LocationTypeTO
import org.ktcs.kernel.persistence.v7.toDomain

/** Where a file older than 6.0.0 keeps the drawing information of its elements. */
internal interface LegacyLayouts {
    fun point(to: PointTO): PointLayout

    fun path(to: PathTO): PathLayout

    fun vehicleColor(to: VehicleTO): String

    fun location(to: LocationTO): LocationLayout

    fun blockColor(to: BlockTO): String

    fun visualLayout(): VisualLayout

    /** Where openTCS's plant overview drew the point, if the file says so apart from its model position. */
    fun drawnPosition(to: PointTO): Couple?

    /** Where openTCS's plant overview drew the location, if the file says so apart from its model position. */
    fun drawnPosition(to: LocationTO): Couple?
}

/**
 * Converts the elements of a 0.0.2 to 0.0.5 file as openTCS 6 does:
 * - `REPORT_POSITION` points become `HALT_POSITION`; peripheral operations triggered `BEFORE_MOVEMENT` become
 *   `AFTER_ALLOCATION`;
 * - a vehicle's `length` becomes the length of its bounding box (width and height 1000), points get the default
 *   maximum vehicle bounding box;
 * - a location (type)'s symbol comes from its `tcs:defaultLocationSymbol` (`tcs:defaultLocationTypeSymbol`) property;
 *   kTCS falls back to the layout element when the property is missing or names no symbol;
 * - missing optional attributes get the domain defaults (z 0, orientation NaN, path length 1, …).
 */
internal fun LegacyPlantModelTO.toDomain(layouts: LegacyLayouts, warnings: ReadWarnings): PlantModel {
    val drawn = DrawnPositions(layouts, warnings)
    return toDomain(layouts).let { model ->
        model.copy(
            points = model.points.zip(point) { domain, to -> drawn.point(domain, to) },
            locations = model.locations.zip(location) { domain, to -> drawn.location(domain, to) },
        ).also { drawn.report() }
    }
}

private fun LegacyPlantModelTO.toDomain(layouts: LegacyLayouts): PlantModel = PlantModel(
    name = name,
    points = point.map { it.toDomain(layouts.point(it)) },
    paths = path.map { it.toDomain(layouts.path(it)) },
    vehicles = vehicle.map { it.toDomain(layouts.vehicleColor(it)) },
    locationTypes = locationType.map { it.toLegacyDomain() },
    locations = location.map { it.toDomain(layouts.location(it)) },
    blocks = block.map { it.toDomain(layouts.blockColor(it)) },
    visualLayout = layouts.visualLayout(),
    properties = property.toMap(),
)

private fun PointTO.toDomain(layout: PointLayout) = Point(
    name = name,
    pose = Pose(Position(xPosition, yPosition, zPosition ?: 0), vehicleOrientationAngle ?: Double.NaN),
    type = when (type) {
        PointTypeTO.REPORT_POSITION, PointTypeTO.HALT_POSITION -> PointType.HALT_POSITION
        PointTypeTO.PARK_POSITION -> PointType.PARK_POSITION
    },
    vehicleEnvelopes = vehicleEnvelope.toDomain(),
    layout = layout,
    properties = property.toMap(),
)

private fun PathTO.toDomain(layout: PathLayout) = Path(
    name = name,
    sourcePoint = sourcePoint,
    destinationPoint = destinationPoint,
    length = length ?: Path(name, sourcePoint, destinationPoint).length,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    peripheralOperations = peripheralOperation.map {
        PeripheralOperation(it.name, it.locationName, it.executionTrigger.toDomain(), it.completionRequired)
    },
    locked = locked,
    vehicleEnvelopes = vehicleEnvelope.toDomain(),
    layout = layout,
    properties = property.toMap(),
)

private fun ExecutionTriggerTO.toDomain() = when (this) {
    ExecutionTriggerTO.BEFORE_MOVEMENT, ExecutionTriggerTO.AFTER_ALLOCATION -> ExecutionTrigger.AFTER_ALLOCATION
    ExecutionTriggerTO.AFTER_MOVEMENT -> ExecutionTrigger.AFTER_MOVEMENT
}

private fun VehicleTO.toDomain(color: String): Vehicle {
    val defaults = Vehicle(name)
    val thresholds = defaults.energyLevelThresholdSet
    return defaults.copy(
        energyLevelThresholdSet = EnergyLevelThresholdSet(
            critical = energyLevelCritical ?: thresholds.critical,
            good = energyLevelGood ?: thresholds.good,
            sufficientlyRecharged = energyLevelSufficientlyRecharged ?: thresholds.sufficientlyRecharged,
            fullyRecharged = energyLevelFullyRecharged ?: thresholds.fullyRecharged,
        ),
        maxVelocity = maxVelocity ?: defaults.maxVelocity,
        maxReverseVelocity = maxReverseVelocity ?: defaults.maxReverseVelocity,
        boundingBox = BoundingBox(length = length ?: defaults.boundingBox.length),
        envelopeKey = envelopeKey,
        layout = defaults.layout.copy(routeColor = color),
        properties = property.toMap(),
    )
}

private fun LocationTypeTO.toLegacyDomain(): LocationType {
    val fallback = locationTypeLayout?.locationRepresentation ?: LocationRepresentation.NONE
    val symbol = property.toMap().symbol(LOCATION_TYPE_SYMBOL) ?: fallback
    return toDomain().copy(layout = LocationTypeLayout(symbol))
}

private fun LocationTO.toDomain(layout: LocationLayout): Location {
    val properties = property.toMap()
    val symbol = properties.symbol(LOCATION_SYMBOL) ?: layout.locationRepresentation
    return Location(
        name = name,
        type = type,
        position = Position(xPosition ?: 0, yPosition ?: 0, zPosition ?: 0),
        links = link.map { it.toDomain() },
        locked = locked,
        layout = layout.copy(locationRepresentation = symbol),
        properties = properties,
    )
}

private fun BlockTO.toDomain(color: String) = Block(
    name = name,
    type = type ?: BlockType.SINGLE_VEHICLE_ONLY,
    members = member.mapTo(LinkedHashSet()) { it.name },
    layout = BlockLayout(color),
    properties = property.toMap(),
)

private const val LOCATION_SYMBOL = "tcs:defaultLocationSymbol"
private const val LOCATION_TYPE_SYMBOL = "tcs:defaultLocationTypeSymbol"

private fun Map<String, String>.symbol(key: String): LocationRepresentation? =
    LocationRepresentation.entries.firstOrNull { it.name == get(key) }
