package org.ktcs.kernel.routing

import org.ktcs.api.model.BoundingBox

/**
 * Whether this box sticks out of [limit] when both are placed on the same reference point: further to the front, the
 * back, either side, or higher. The reference offsets matter, so a box no larger than [limit] may still protrude.
 */
internal fun BoundingBox.protrudesBeyond(limit: BoundingBox): Boolean {
    val own = reach()
    val allowed = limit.reach()
    return own.zip(allowed).any { (distance, maximum) -> distance > maximum } || height > limit.height
}

/** Twice the distances from the reference point to the front, back, left and right sides (doubled to stay whole). */
private fun BoundingBox.reach(): List<Long> = listOf(
    length - 2 * referenceOffset.x,
    length + 2 * referenceOffset.x,
    width - 2 * referenceOffset.y,
    width + 2 * referenceOffset.y,
)
