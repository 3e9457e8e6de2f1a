package org.ktcs.kernel.persistence.v7

import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Envelope
import org.ktcs.api.model.Layer
import org.ktcs.api.model.LayerGroup
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.LocationTypeLayout
import org.ktcs.api.model.Path
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PeripheralOperation
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.persistence.CoupleTO
import org.ktcs.kernel.persistence.toMap

/**
 * Maps a 7.0.0 or 6.0.0 file to the domain model. `outgoingPath` elements are ignored: outgoing paths are derived
 * from the paths. Optional layout elements that are missing get the domain defaults. Dropped from 6.0.0 files, as
 * openTCS drops them: the layout positions of points and locations (`pointLayout`/`locationLayout` `positionX`,
 * `positionY`).
 */
internal fun V7PlantModelTO.toDomain(): PlantModel = PlantModel(
    name = name,
    points = point.map { it.toDomain() },
    paths = path.map { it.toDomain() },
    vehicles = vehicle.map { it.toDomain() },
    locationTypes = locationType.map { it.toDomain() },
    locations = location.map { it.toDomain() },
    blocks = block.map { it.toDomain() },
    visualLayout = visualLayout?.toDomain() ?: VisualLayout(),
    properties = property.toMap(),
)

private fun PointTO.toDomain() = Point(
    name = name,
    pose = Pose(Position(positionX, positionY, positionZ), vehicleOrientationAngle ?: Double.NaN),
    type = type,
    maxVehicleBoundingBox = maxVehicleBoundingBox.toDomain(),
    vehicleEnvelopes = vehicleEnvelope.toDomain(),
    layout = pointLayout?.let { PointLayout(Couple(it.labelOffsetX, it.labelOffsetY), it.layerId) } ?: PointLayout(),
    properties = property.toMap(),
)

private fun PathTO.toDomain() = Path(
    name = name,
    sourcePoint = sourcePoint,
    destinationPoint = destinationPoint,
    length = length,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    peripheralOperations = peripheralOperation.map {
        PeripheralOperation(it.name, it.locationName, it.executionTrigger, it.completionRequired)
    },
    locked = locked,
    vehicleEnvelopes = vehicleEnvelope.toDomain(),
    layout = pathLayout?.let { PathLayout(it.connectionType, it.controlPoint.toCouples(), it.layerId) } ?: PathLayout(),
    properties = property.toMap(),
)

private fun VehicleTO.toDomain() = Vehicle(
    name = name,
    energyLevelThresholdSet = EnergyLevelThresholdSet(
        critical = energyLevelCritical,
        good = energyLevelGood,
        sufficientlyRecharged = energyLevelSufficientlyRecharged,
        fullyRecharged = energyLevelFullyRecharged,
    ),
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    boundingBox = boundingBox.toDomain(),
    envelopeKey = envelopeKey,
    layout = vehicleLayout?.let { VehicleLayout(it.color) } ?: VehicleLayout(),
    properties = property.toMap(),
)

internal fun LocationTypeTO.toDomain() = LocationType(
    name = name,
    allowedOperations = allowedOperation.mapTo(LinkedHashSet()) { it.name },
    allowedPeripheralOperations = allowedPeripheralOperation.mapTo(LinkedHashSet()) { it.name },
    layout = locationTypeLayout?.let { LocationTypeLayout(it.locationRepresentation) } ?: LocationTypeLayout(),
    properties = property.toMap(),
)

private fun LocationTO.toDomain() = Location(
    name = name,
    type = type,
    position = Position(positionX, positionY, positionZ),
    links = link.map { it.toDomain() },
    locked = locked,
    layout = locationLayout?.toDomain() ?: LocationLayout(),
    properties = property.toMap(),
)

private fun LocationLayoutTO.toDomain() =
    LocationLayout(Couple(labelOffsetX, labelOffsetY), locationRepresentation, layerId)

internal fun LinkTO.toDomain() = Link(point, allowedOperation.mapTo(LinkedHashSet()) { it.name })

private fun BlockTO.toDomain() = Block(
    name = name,
    type = type,
    members = member.mapTo(LinkedHashSet()) { it.name },
    layout = blockLayout?.let { BlockLayout(it.color) } ?: BlockLayout(),
    properties = property.toMap(),
)

internal fun VisualLayoutTO.toDomain() = VisualLayout(
    name = name,
    scaleX = scaleX,
    scaleY = scaleY,
    layers = layer.map { Layer(it.id, it.ordinal, it.visible, it.name, it.groupId) },
    layerGroups = layerGroup.map { LayerGroup(it.id, it.name, it.visible) },
    properties = property.toMap(),
)

internal fun BoundingBoxTO.toDomain() = BoundingBox(length, width, height, Couple(referenceOffsetX, referenceOffsetY))

internal fun List<VehicleEnvelopeTO>.toDomain(): Map<String, Envelope> =
    associate { it.key to Envelope(it.vertex.toCouples()) }

internal fun List<CoupleTO>.toCouples(): List<Couple> = map { Couple(it.x, it.y) }
