package org.ktcs.kernel.persistence.v7

import org.ktcs.api.model.Block
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple
import org.ktcs.api.model.Envelope
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.persistence.CoupleTO
import org.ktcs.kernel.persistence.toPropertyTOs
import org.ktcs.kernel.persistence.toSortedNameTOs

/** The version string of the files kTCS writes. */
internal const val V7_VERSION = "7.0.0"

/**
 * Maps a model to the 7.0.0 file layout. Elements keep the model's order; like openTCS, the writer sorts what the
 * domain holds as sets or maps (properties, members, operations, envelopes) and derives `outgoingPath` elements from
 * the paths.
 */
internal fun PlantModel.toV7(): V7PlantModelTO = V7PlantModelTO(
    version = V7_VERSION,
    name = name,
    point = points.map { it.toV7(outgoingPaths(it.name)) },
    path = paths.map { it.toV7() },
    vehicle = vehicles.map { it.toV7() },
    locationType = locationTypes.map { it.toV7() },
    location = locations.map { it.toV7() },
    block = blocks.map { it.toV7() },
    visualLayout = visualLayout.toV7(),
    property = properties.toPropertyTOs(),
)

private fun Point.toV7(outgoing: List<Path>) = PointTO(
    name = name,
    positionX = pose.position.x,
    positionY = pose.position.y,
    positionZ = pose.position.z,
    vehicleOrientationAngle = pose.orientationAngle,
    type = type,
    maxVehicleBoundingBox = maxVehicleBoundingBox.toV7(),
    vehicleEnvelope = vehicleEnvelopes.toV7(),
    outgoingPath = outgoing.map { it.name }.toSortedNameTOs(),
    property = properties.toPropertyTOs(),
    pointLayout = PointLayoutTO(layout.labelOffset.x, layout.labelOffset.y, layout.layerId),
)

private fun Path.toV7() = PathTO(
    name = name,
    sourcePoint = sourcePoint,
    destinationPoint = destinationPoint,
    length = length,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    locked = locked,
    peripheralOperation = peripheralOperations.map {
        PeripheralOperationTO(it.completionRequired, it.executionTrigger, it.location, it.operation)
    },
    vehicleEnvelope = vehicleEnvelopes.toV7(),
    property = properties.toPropertyTOs(),
    pathLayout = PathLayoutTO(layout.connectionType, layout.layerId, layout.controlPoints.toCoupleTOs()),
)

private fun Vehicle.toV7() = VehicleTO(
    name = name,
    energyLevelCritical = energyLevelThresholdSet.critical,
    energyLevelGood = energyLevelThresholdSet.good,
    energyLevelFullyRecharged = energyLevelThresholdSet.fullyRecharged,
    energyLevelSufficientlyRecharged = energyLevelThresholdSet.sufficientlyRecharged,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    envelopeKey = envelopeKey,
    boundingBox = boundingBox.toV7(),
    property = properties.toPropertyTOs(),
    vehicleLayout = ColorTO(layout.routeColor),
)

private fun LocationType.toV7() = LocationTypeTO(
    name = name,
    allowedOperation = allowedOperations.toSortedNameTOs(),
    allowedPeripheralOperation = allowedPeripheralOperations.toSortedNameTOs(),
    property = properties.toPropertyTOs(),
    locationTypeLayout = LocationTypeLayoutTO(layout.locationRepresentation),
)

private fun Location.toV7() = LocationTO(
    name = name,
    positionX = position.x,
    positionY = position.y,
    positionZ = position.z,
    locked = locked,
    type = type,
    link = links.map { LinkTO(it.point, it.allowedOperations.toSortedNameTOs()) },
    property = properties.toPropertyTOs(),
    locationLayout = LocationLayoutTO(
        layout.labelOffset.x,
        layout.labelOffset.y,
        layout.locationRepresentation,
        layout.layerId,
    ),
)

private fun Block.toV7() = BlockTO(
    name = name,
    type = type,
    member = members.toSortedNameTOs(),
    property = properties.toPropertyTOs(),
    blockLayout = ColorTO(layout.color),
)

private fun VisualLayout.toV7() = VisualLayoutTO(
    name = name,
    scaleX = scaleX,
    scaleY = scaleY,
    layer = layers.map { LayerTO(it.id, it.ordinal, it.visible, it.name, it.groupId) },
    layerGroup = layerGroups.map { LayerGroupTO(it.id, it.name, it.visible) },
    property = properties.toPropertyTOs(),
)

private fun BoundingBox.toV7() = BoundingBoxTO(length, width, height, referenceOffset.x, referenceOffset.y)

private fun Map<String, Envelope>.toV7(): List<VehicleEnvelopeTO> =
    entries.sortedBy { it.key }.map { VehicleEnvelopeTO(it.key, it.value.vertices.toCoupleTOs()) }

private fun List<Couple>.toCoupleTOs(): List<CoupleTO> = map { CoupleTO(it.x, it.y) }
