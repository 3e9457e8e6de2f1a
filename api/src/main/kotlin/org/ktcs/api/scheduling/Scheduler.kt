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

    /** What every waiting client asked for and has not got yet, by client name, oldest request first. */
    public fun pendingAllocations(): Map<String, List<Set<String>>>
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
}
