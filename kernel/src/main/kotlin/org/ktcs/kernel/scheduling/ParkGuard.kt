package org.ktcs.kernel.scheduling

import org.slf4j.LoggerFactory

/**
 * Applies [ParkSafety] to the scheduler's state: a grant is made only if, once the grantee has driven there, every
 * vehicle could still get off the lanes into a park point; and a vehicle held back can be sent to retreat through a
 * free park point. Off (logged once) while the plant has fewer park points than vehicles holding something.
 *
 * @param holdings what each client holds, as deadlock avoidance counts it.
 * @param front the point each client stands on or was granted last and still holds, if known.
 * @param inBlock whether a resource belongs to a SINGLE_VEHICLE_ONLY block (a vehicle in one may leave by any of its
 *   points).
 */
internal class ParkGuard(
    private val parks: ParkSafety,
    private val clients: () -> Set<String>,
    private val holdings: (String) -> Set<String>,
    private val front: (String) -> String?,
    private val inBlock: (String) -> Boolean,
) {
    private var warned = false

    /** How many grants were held back because the state after them would not have been safe. */
    var heldBack = 0L
        private set

    /** Whether granting [client] the step ending at [point], after which it holds [heldAfter], keeps the state safe. */
    fun mayGrant(client: String, point: String?, heldAfter: Set<String>): Boolean {
        val at = point?.let(parks::pointIndex)?.takeIf { it >= 0 } ?: return true
        val fleet = fleet(standing(client, at, heldAfter)) ?: return true
        if (parks.isSafe(fleet)) return true
        heldBack++
        return false
    }

    /** The nearest free park point [client] can drive to now over points nobody holds, or null. */
    fun retreatPoint(client: String): String? {
        val fleet = fleet(null) ?: return null
        return fleet.firstOrNull { it.name == client }?.let { parks.retreatPoint(fleet, it) }
    }

    // The fleet as it stands, [grantee] as it will stand after its grant; null while the test is off.
    private fun fleet(grantee: Standing?): List<Standing>? {
        val fleet = ArrayList<Standing>()
        grantee?.let(fleet::add)
        for (client in clients()) {
            if (client == grantee?.name) continue
            val holds = holdings(client)
            val at = front(client)?.let(parks::pointIndex)?.takeIf { it >= 0 }
                ?: holds.firstNotNullOfOrNull { parks.pointIndex(it).takeIf { i -> i >= 0 } } ?: continue
            fleet += standing(client, at, holds)
        }
        if (fleet.size <= parks.parkPoints) return fleet
        if (!warned) {
            warned = true
            log.info(
                "deadlock avoidance: {} vehicles but {} park points, so the park test is off and the local rule " +
                    "works alone",
                fleet.size,
                parks.parkPoints,
            )
        }
        return null
    }

    private fun standing(client: String, at: Int, holds: Set<String>): Standing {
        val exits = holds.filter(inBlock).map(parks::pointIndex).filter { it >= 0 && it != at }
        return Standing(client, at, indices(holds), if (exits.isEmpty()) intArrayOf(at) else (exits + at).toIntArray())
    }

    private fun indices(keys: Set<String>): IntArray =
        keys.asSequence().map(parks::pointIndex).filter { it >= 0 }.toList().toIntArray()

    private companion object {
        private val log = LoggerFactory.getLogger(ParkGuard::class.java)
    }
}

private typealias Standing = ParkSafety.Standing
