package org.ktcs.kernel.core

import org.ktcs.kernel.scheduling.DefaultScheduler
import org.slf4j.LoggerFactory

/**
 * Gets a fleet moving that deadlock avoidance holds back without a deadlock: each vehicle held back that can drive into
 * a free park point over free points now is sent on through it (a *retreat*), which frees its point for the vehicles
 * behind it, oldest hold first, each into a bay no other retreat is bound for. A vehicle is not sent again for
 * [COOLDOWN_CHECKS] checks, so retreats that do not help cannot keep the fleet circling through park bays. The watchdog also breaks a
 * deadlock by a retreat ([breakCycle]) where routing around it does not, or did not last.
 */
internal class Retreats(private val kernel: KernelCore) {
    private val log = LoggerFactory.getLogger(Retreats::class.java)
    private val lastSent = HashMap<String, Long>()
    private val targets = RetreatTargets()
    private val sideSteps = SideSteps()
    private val sideStepsTaken = TakenSideSteps(COOLDOWN_CHECKS)
    private var checks = 0L

    /** How many retreats were sent. */
    var sent = 0
        private set

    /** Sends the vehicles held back that can retreat now; returns whether it sent any. */
    fun check(): Boolean {
        val scheduler = kernel.scheduler
        checks++
        scheduler.retryOverdue()
        if (lastSent.size > 64) lastSent.values.removeIf { checks - it >= COOLDOWN_CHECKS }
        sideStepsTaken.forgetOld(checks)
        targets.update(checks, scheduler::allocationsOf)
        val ready = { vehicle: String -> lastSent[vehicle]?.let { checks - it < COOLDOWN_CHECKS } != true }
        // Every vehicle that can retreat now, each to a bay of its own: one per check was too few where most of the
        // fleet is held back and a check spans many moves (a warehouse at time factor 100 stalled through the web API).
        return scheduler.retreats(ready).count {
            send(it.vehicle, it.parkPoint, scheduler.allocations(), "held back")
        } > 0
    }

    /**
     * Sends one vehicle of a deadlock that no reroute breaks on through a free park point it reaches now, else through
     * a free point nearby that the others of the [knot] do not need ([SideSteps]).
     */
    fun breakCycle(vehicles: List<String>, sideSteps: Boolean = true, knot: List<String> = vehicles): Boolean {
        val allocations = kernel.scheduler.allocations()
        return vehicles.any { vehicle -> retreatOf(vehicle, allocations) } ||
            (sideSteps && vehicles.any { stepAside(it, knot, allocations) })
    }

    // A retreat through a bay the vehicle went through lately for a deadlock is not offered again: where it did not
    // help, the vehicle came straight back into the same knot, and was sent through the same bay again, 634 times in
    // one run of the warehouse (virtual time, seed 9), while the vehicle it made room for stayed where it was.
    private fun retreatOf(vehicle: String, allocations: Map<String, Set<String>>): Boolean {
        val park = kernel.scheduler.retreatPoint(vehicle) ?: return false
        if (sideStepsTaken.isRecent(vehicle, park, checks)) return false
        return send(vehicle, park, allocations, "of a deadlock").also { sent ->
            if (sent) sideStepsTaken.add(vehicle, park, checks)
        }
    }

    // A head-on meeting at a dead-end stub's mouth has no way around and often no free bay in reach (real time
    // stalled the warehouse that way in 3 of 5 runs through the web API): one of the two steps aside instead. A side
    // step the vehicle took lately is not offered again: where it did not help, the vehicle came straight back into
    // the same knot, and the watchdog sent it to the same point hundreds of times (twice a second through the web
    // API) while the fleet stood still; another vehicle of the knot, or another point, gets the next try.
    private fun stepAside(vehicle: String, knot: List<String>, allocations: Map<String, Set<String>>): Boolean {
        val from = kernel.plant.vehicle(vehicle).currentPosition ?: return false
        val needs = (kernel.scheduler as? DefaultScheduler)?.let { scheduler -> scheduler::needs }
        val needed = knot.filter { it != vehicle }.flatMapTo(HashSet()) { needs?.invoke(it).orEmpty() }
        val held = HashSet<String>()
        allocations.forEach { (holder, resources) -> if (holder != vehicle) held += resources }
        return sideSteps.near(kernel.plant.layoutWithLocks(), from, held::contains, needed::contains)
            .filterNot { sideStepsTaken.isRecent(vehicle, it, checks) }
            .any { point ->
                send(vehicle, point, allocations, "of a deadlock, stepping aside").also { sent ->
                    if (sent) sideStepsTaken.add(vehicle, point, checks)
                }
            }
    }

    private fun send(vehicle: String, park: String, allocations: Map<String, Set<String>>, why: String): Boolean {
        if (targets.isTargetOfAnother(park, vehicle)) return false
        val occupied = allocations.filterKeys { it != vehicle }.values.flatMapTo(HashSet()) { it }
        if (!kernel.retreat(vehicle, park, occupied)) return false
        lastSent[vehicle] = checks
        targets.add(vehicle, park, checks)
        sent++
        log.info("traffic: vehicle {} {}, sent on through park point {}", vehicle, why, park)
        return true
    }

    private companion object {
        const val COOLDOWN_CHECKS = 60L
    }
}

/** The side steps vehicles took ([Retreats]), each remembered for [memoryChecks] watchdog checks. */
internal class TakenSideSteps(private val memoryChecks: Long) {
    private val takenAt = HashMap<Pair<String, String>, Long>()

    fun add(vehicle: String, point: String, check: Long) {
        takenAt[vehicle to point] = check
    }

    /** Whether [vehicle] stepped aside to [point] within the last [memoryChecks] checks before [check]. */
    fun isRecent(vehicle: String, point: String, check: Long): Boolean =
        takenAt[vehicle to point]?.let { check - it < memoryChecks } == true

    /** Forgets the side steps older than the memory, so the map holds only the recent ones. */
    fun forgetOld(check: Long) {
        if (takenAt.isNotEmpty()) takenAt.values.removeIf { check - it >= memoryChecks }
    }
}

/**
 * The park points retreats were sent to, each until its vehicle has been in and out again (or for at most
 * [MAX_CHECKS] checks: its route may have changed since). Two vehicles sent into the same dead-end bay meet head-on
 * at its mouth, each waiting for the other.
 */
private class RetreatTargets {
    private class Target(val park: String, val sentAt: Long) {
        var reached = false
    }

    private val targets = HashMap<String, Target>()

    fun isTargetOfAnother(park: String, vehicle: String): Boolean =
        targets.any { (other, target) -> other != vehicle && target.park == park }

    fun add(vehicle: String, park: String, check: Long) {
        targets[vehicle] = Target(park, check)
    }

    /** Forgets the targets reached and left again, and those sent too long ago, by what each vehicle holds now. */
    fun update(check: Long, holdingsOf: (String) -> Set<String>) {
        if (targets.isEmpty()) return
        targets.entries.removeIf { (vehicle, target) ->
            val inside = target.park in holdingsOf(vehicle)
            if (inside) target.reached = true
            (target.reached && !inside) || check - target.sentAt >= MAX_CHECKS
        }
    }

    private companion object {
        const val MAX_CHECKS = 120L
    }
}
