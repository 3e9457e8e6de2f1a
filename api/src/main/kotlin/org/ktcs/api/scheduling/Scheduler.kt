package org.ktcs.api.scheduling

import org.ktcs.api.kernel.KernelComponent
import org.ktcs.api.model.PlantModel

/**
 * Grants vehicles exclusive use of resources (points, paths and locations, named by their unique names), so that
 * no resource is ever held by two vehicles.
 *
 * The protocol, for each vehicle (a [SchedulerClient]):
 * 1. [claim] the resources of the whole route ahead, one set per movement step, so the scheduler knows the future;
 * 2. [allocate] the next set; the scheduler grants it at once or as soon as it is free, through
 *    [SchedulerClient.onAllocationGranted], in the kernel context; a vehicle whose resources are taken waits;
 * 3. [free] what lies behind the vehicle; [freeAll] when it leaves the plant or its order ends.
 *
 * Blocks extend a request: a SINGLE_VEHICLE_ONLY block is taken as a whole; vehicles may share a SAME_DIRECTION_ONLY
 * block only while they all enter it in the same direction. A paused vehicle is granted nothing new.
 */
public interface Scheduler : KernelComponent {
    /**
     * The plant model was replaced by [model]. No vehicle is on its way at that moment; forget every claim,
     * allocation and pending request, and use the blocks of [model] from now on.
     */
    public fun updatePlantModel(model: PlantModel)

    /** Replaces the client's claim with [resources], one set per step ahead, in driving order. */
    public fun claim(client: SchedulerClient, resources: List<Set<String>>)

    /** Forgets the client's claim. */
    public fun unclaim(client: SchedulerClient)

    /** Requests [resources]; granted now or later through [SchedulerClient.onAllocationGranted]. */
    public fun allocate(client: SchedulerClient, resources: Set<String>)

    /**
     * Allocates [resources] immediately, whoever else holds them, e.g. where a vehicle reports that it already is.
     * Use with care: it is the one way to break exclusivity, and the kernel reports it.
     */
    public fun allocateNow(client: SchedulerClient, resources: Set<String>)

    /** Withdraws the client's requests that were not granted yet. */
    public fun clearPendingAllocations(client: SchedulerClient)

    /** Gives [resources] back. */
    public fun free(client: SchedulerClient, resources: Set<String>)

    /** Gives everything the client holds back, and forgets its claim and pending requests. */
    public fun freeAll(client: SchedulerClient)

    /** Pauses or resumes granting resources to the client. */
    public fun setPaused(client: SchedulerClient, paused: Boolean)

    /** What every client holds, by client name. */
    public fun allocations(): Map<String, Set<String>>

    /**
     * What the client named [client] holds: its entry of [allocations]. A scheduler that can answer for one client
     * without copying every client's holdings should: the kernel's watchdog asks this of a few vehicles per check.
     */
    public fun allocationsOf(client: String): Set<String> = allocations()[client].orEmpty()

    /** What every waiting client asked for and has not got yet, by client name, oldest request first. */
    public fun pendingAllocations(): Map<String, List<Set<String>>>

    /**
     * Who each waiting client waits for: by waiter name, the clients standing in its way, each with the resources it
     * waits for them to give up. The kernel's deadlock watchdog looks for cycles in it and breaks one by routing a
     * vehicle around the contested resources; it asks only this interface, so it keeps working with any scheduler.
     *
     * The default derives it from [allocations] and [pendingAllocations]: a client waits for every holder of a
     * resource of its oldest pending request (its later requests cannot be granted before that one anyway). A
     * scheduler that holds requests back for other reasons too (blocks, deadlock avoidance) should add those waits,
     * or the watchdog will not see the deadlocks they take part in. Called in the kernel context.
     */
    public fun waitsFor(): Map<String, Map<String, Set<String>>> =
        SchedulerWaits.of(allocations(), pendingAllocations())

    /**
     * Whether [client]'s claim makes it wait, through others, for itself: the first step of its claimed route leads
     * into vehicles that wait for what it stands on. A claim cannot be refused, so the vehicle then routes around
     * that step before it starts. The default, `false`, suits a scheduler that does not look ahead along claims.
     * Called in the kernel context.
     */
    public fun claimIsBlocked(client: SchedulerClient): Boolean = false

    /**
     * Whether [claimIsBlocked] would hold if [client] claimed [resources] (as for [claim]) instead of its current
     * claim, which stays as it is. The kernel asks before it routes a vehicle anew to break a deadlock or to avoid a
     * blocked start: a new route that closes another cycle of waiting vehicles is not taken. The default, `false`,
     * suits a scheduler that does not look ahead along claims. Called in the kernel context.
     */
    public fun claimWouldBeBlocked(client: SchedulerClient, resources: List<Set<String>>): Boolean = false

    /**
     * What makes [client]'s claim blocked ([claimIsBlocked]): the resources it needs next that vehicles waiting, through
     * others, for it hold. The kernel routes a vehicle whose claim is blocked around them where the plant allows (on a
     * two-way aisle the vehicles it would meet head-on, not only its first step). The default, empty, suits a
     * scheduler that does not look ahead along claims. Called in the kernel context.
     */
    public fun claimBlockers(client: SchedulerClient): Set<String> = emptySet()

    /**
     * The vehicles whose next grant deadlock avoidance has held back for a while although no deadlock holds them, and
     * that could drive into a free park point now, longest held back first. The deadlock watchdog sends one of them on
     * through its park point per check (a *retreat*), which frees its point for the vehicles behind it. Only clients
     * [eligible] accepts are offered (the watchdog leaves out those it sent recently), so a lazy sequence searches
     * for no park point it need not. The default, none, suits a scheduler that holds no grant back for safety.
     * Called in the kernel context.
     */
    public fun retreats(eligible: (String) -> Boolean): Sequence<Retreat> = emptySequence()

    /**
     * The nearest free park point [client] could drive into now over points nobody holds, or null: where the
     * watchdog sends a vehicle of a deadlock that no new route breaks. The default, null, suits a scheduler that
     * keeps no such view of the plant. Called in the kernel context.
     */
    public fun retreatPoint(client: String): String? = null

    /**
     * Called by the deadlock watchdog on each of its checks, while nothing else changes: a scheduler that holds a
     * grant back only for a limited time decides the overdue ones again. The default does nothing. Called in the
     * kernel context.
     */
    public fun retryOverdue() {}

    /** How many grants deadlock avoidance has held back so far (each one until it was safe); the default is 0. */
    public val grantsHeldBack: Long get() = 0
}

/** A [vehicle] held back that could drive into the free [parkPoint] now ([Scheduler.retreats]). */
public data class Retreat(val vehicle: String, val parkPoint: String)

/** How waits follow from what clients hold and request, as [Scheduler.waitsFor] derives them by default. */
public object SchedulerWaits {
    /**
     * For each client with a pending request, the holders of the resources of its oldest one (its later requests
     * cannot be granted before that one anyway), each with those resources; clients that wait for nobody are left out.
     */
    public fun of(
        allocations: Map<String, Set<String>>,
        pending: Map<String, List<Set<String>>>,
    ): Map<String, Map<String, Set<String>>> {
        val holders = HashMap<String, MutableSet<String>>()
        allocations.forEach { (client, resources) -> resources.forEach { holders.getOrPut(it, ::HashSet) += client } }
        return pending.mapValues { (waiter, requests) -> blockers(waiter, requests.firstOrNull().orEmpty(), holders) }
            .filterValues { it.isNotEmpty() }
    }

    private fun blockers(
        waiter: String,
        request: Set<String>,
        holders: Map<String, Set<String>>,
    ): Map<String, Set<String>> {
        val blockers = HashMap<String, MutableSet<String>>()
        for (resource in request) {
            for (holder in holders[resource].orEmpty() - waiter) blockers.getOrPut(holder, ::HashSet) += resource
        }
        return blockers
    }
}

/** A vehicle as the scheduler sees it. */
public interface SchedulerClient {
    /** The vehicle's name. */
    public val name: String

    /**
     * The scheduler granted [resources]. Return `false` if the client no longer wants them (e.g. its order was
     * withdrawn meanwhile); the scheduler then frees them again.
     */
    public fun onAllocationGranted(resources: Set<String>): Boolean

    /**
     * What the client will still hold besides [resources] once it has driven up to them: the resources its length
     * still covers behind it. Deadlock avoidance counts them as held after a grant of [resources]; the default,
     * nothing, suits vehicles that are short compared with the paths.
     */
    public fun heldAfter(resources: Set<String>): Set<String> = emptySet()

    /**
     * As [heldAfter], two or more steps ahead: what the client will still hold besides the last of [steps] once it has
     * driven up to it through all of them (none granted yet). The default counts every step but the last as still
     * covered, which is safe for any length; a client that knows its length answers more closely.
     */
    public fun heldAfter(steps: List<Set<String>>): Set<String> =
        heldAfter(steps.last()) + steps.dropLast(1).flatten() - steps.last()
}
