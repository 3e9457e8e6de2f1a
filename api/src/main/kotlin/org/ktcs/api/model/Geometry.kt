package org.ktcs.api.model

/** A position in the plant, in millimetres. */
public data class Position(val x: Long, val y: Long, val z: Long = 0)

/** A two-dimensional offset or vertex, in millimetres (or pixels where a layout says so). */
public data class Couple(val x: Long, val y: Long)

/**
 * A position with an orientation.
 *
 * @property orientationAngle degrees, 0 pointing along +x ("3 o'clock"), counter-clockwise positive; `NaN` when unknown.
 */
public data class Pose(val position: Position, val orientationAngle: Double = Double.NaN)

/**
 * The space a vehicle occupies, or the largest one a point tolerates, in millimetres.
 *
 * @property referenceOffset offset of the vehicle's reference point from the box's base centre (+x forward, +y left).
 */
public data class BoundingBox(
    val length: Long = 1000,
    val width: Long = 1000,
    val height: Long = 1000,
    val referenceOffset: Couple = Couple(0, 0),
)

/** A polygon a vehicle with a matching envelope key occupies at a point or on a path. */
public data class Envelope(val vertices: List<Couple>)
