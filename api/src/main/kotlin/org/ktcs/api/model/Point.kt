package org.ktcs.api.model

/** A node of the roadmap where vehicles may stop. */
public data class Point(
    override val name: String,
    val pose: Pose = Pose(Position(0, 0, 0)),
    val type: PointType = PointType.HALT_POSITION,
    val maxVehicleBoundingBox: BoundingBox = BoundingBox(),
    val vehicleEnvelopes: Map<String, Envelope> = emptyMap(),
    val layout: PointLayout = PointLayout(),
    override val properties: Map<String, String> = emptyMap(),
) : PlantObject

/** What a vehicle may do at a point. */
public enum class PointType {
    /** A vehicle may stop here, but not park. */
    HALT_POSITION,

    /** A vehicle may stop and park here. */
    PARK_POSITION,
}

/** How a point is drawn. */
public data class PointLayout(val labelOffset: Couple = Couple(-10, -20), val layerId: Int = 0)
