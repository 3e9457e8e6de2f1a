package org.ktcs.kernel.core

import org.slf4j.LoggerFactory

/**
 * Gets a fleet moving that deadlock avoidance holds back without a deadlock: the vehicle held back longest that can
 * drive into a free park point over free points now is sent on through it (a *retreat*), which frees its point for
 * the vehicles behind it. One such retreat per watchdog check, and a vehicle is not sent again for [COOLDOWN_CHECKS]
 * checks, so retreats that do not help cannot keep the fleet circling through park bays. The watchdog also breaks a
 * deadlock by a retreat ([breakCycle]) where routing around it does not, or did not last.
 */
internal class Retreats(private val kernel: KernelCore) {
    private val log = LoggerFactory.getLogger(Retreats::class.java)
    private val lastSent = HashMap<String, Long>()
    private var checks = 0L

    /** How many retreats were sent. */
    var sent = 0
        private set

    /** Sends one retreat if a vehicle is held back and can retreat; returns whether it did. */
    fun check(): Boolean {
        val scheduler = kernel.scheduler
        checks++
        scheduler.retryOverdue()
        if (lastSent.size > 64) lastSent.values.removeIf { checks - it >= COOLDOWN_CHECKS }
        val allocations by lazy(LazyThreadSafetyMode.NONE) { scheduler.allocations() }
        val ready = { vehicle: String -> lastSent[vehicle]?.let { checks - it < COOLDOWN_CHECKS } != true }
        return scheduler.retreats(ready).any { send(it.vehicle, it.parkPoint, allocations, "held back") }
    }

    /** Sends one vehicle of a deadlock that no reroute breaks on through a free park point it reaches now. */
    fun breakCycle(vehicles: List<String>): Boolean {
        val scheduler = kernel.scheduler
        val allocations = scheduler.allocations()
        return vehicles.any { vehicle ->
            scheduler.retreatPoint(vehicle)?.let { send(vehicle, it, allocations, "of a deadlock") } == true
        }
    }

    private fun send(vehicle: String, park: String, allocations: Map<String, Set<String>>, why: String): Boolean {
        val occupied = allocations.filterKeys { it != vehicle }.values.flatMapTo(HashSet()) { it }
        if (!kernel.retreat(vehicle, park, occupied)) return false
        lastSent[vehicle] = checks
        sent++
        log.info("traffic: vehicle {} {}, sent on through park point {}", vehicle, why, park)
        return true
    }

    private companion object {
        const val COOLDOWN_CHECKS = 60L
    }
}
