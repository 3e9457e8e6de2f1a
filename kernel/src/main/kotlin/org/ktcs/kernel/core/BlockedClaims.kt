package org.ktcs.kernel.core

import org.ktcs.kernel.scheduling.DefaultScheduler
import org.slf4j.LoggerFactory

/**
 * Gets a vehicle started whose fresh claim waits, through others, for itself, with no way around it: a vehicle in a
 * station stub whose new route leaves past the vehicle waiting at the stub's mouth to come in, or two vehicles in the
 * stubs of one aisle bound for each other's station. A claim cannot be refused, and no grant can undo such a knot, so
 * at the watchdog's next check one of its vehicles yields, before their wait counts as a deadlock (a grant held back
 * counts after two periods): the ones in the claimant's way first, each through a free park bay in reach or a free
 * point nearby, then the claimant ([Retreats.breakCycle]; each yield also counts as a retreat). A knot that no yield
 * breaks within [MAX_TRIES] checks is left to the deadlock search, which reports it. Two standing vehicles whose next
 * steps the local rule holds back for each other get the same treatment, through park bays only.
 */
internal class BlockedClaims(private val kernel: KernelCore, private val state: KernelState) {
    private val log = LoggerFactory.getLogger(BlockedClaims::class.java)
    private val tries = HashMap<String, Int>()

    /** How many blocked claims were unblocked by a yield. */
    var yields = 0
        private set

    fun check(retreating: Retreats) {
        mutualRefusals(retreating)
        val blocked = state.controllers.all().filter { it.claimBlocked }
        if (blocked.isEmpty()) {
            if (tries.isNotEmpty()) tries.clear()
            return
        }
        tries.keys.retainAll(blocked.mapTo(HashSet()) { it.name })
        val scheduler = kernel.scheduler
        for (claimant in blocked) {
            if (!scheduler.claimIsBlocked(claimant)) {
                claimant.claimBlocked = false
                continue
            }
            val allocations = scheduler.allocations()
            val keys = scheduler.claimBlockers(claimant)
            val inTheWay = allocations.filter { (vehicle, held) ->
                vehicle != claimant.name && held.any(keys::contains)
            }
            if (yieldsNearestFirst(claimant.name, inTheWay.keys, retreating)) {
                yields++
                claimant.claimBlocked = false
                log.info(
                    "traffic: vehicle {} has a route blocked by {}; one of them yields",
                    claimant.name,
                    inTheWay.keys,
                )
                continue
            }
            val tried = (tries[claimant.name] ?: 0) + 1
            tries[claimant.name] = tried
            if (tried >= MAX_TRIES) claimant.claimBlocked = false
        }
    }

    // The vehicles waiting for what the claimant stands on yield first, by a retreat or a side step (a vehicle queued
    // at a station stub's mouth for the station the claimant is leaving, on the side its route leaves by): a retreat
    // of a vehicle further along the queue, tried first when all went by name, left that knot as it was.
    private fun yieldsNearestFirst(claimant: String, inTheWay: Set<String>, retreating: Retreats): Boolean {
        val waits = kernel.scheduler.waitsFor()
        val nearest = inTheWay.filter { waits[it]?.containsKey(claimant) == true }.sorted()
        val knot = inTheWay.sorted() + claimant
        return (nearest.isNotEmpty() && retreating.breakCycle(nearest, knot = knot)) || retreating.breakCycle(knot)
    }

    // Standing vehicles whose next steps the local rule holds back for each other: no grant can undo that either, so
    // one of them retreats through a free park bay at once, without side steps (those moved vehicles into worse
    // knots on the random plants), before the wait counts as a deadlock (developer's guide, 12, "Session 32").
    private fun mutualRefusals(retreating: Retreats) {
        val scheduler = kernel.scheduler as? DefaultScheduler ?: return
        for (claimant in state.controllers.all()) {
            if (claimant.sent.isNotEmpty() || claimant.currentOrder == null) continue
            val others = scheduler.refusedMutually(claimant.name)
            if (others.isEmpty()) continue
            if (retreating.breakCycle(others.sorted() + claimant.name, sideSteps = false)) {
                yields++
                log.info("traffic: vehicles {} and {} hold each other back; one of them yields", claimant.name, others)
            }
        }
    }

    private companion object {
        const val MAX_TRIES = 3
    }
}
