package org.ktcs.api.service

import org.ktcs.api.model.PlantModel

/** Reads and changes the plant. Every method may be called from any coroutine. */
public interface PlantModelService {
    /** The plant as it is now, with current locks and vehicle states. */
    public suspend fun plantModel(): PlantModel

    /** Locks or unlocks a path; the router stops or starts using it at once. */
    public suspend fun setPathLocked(path: String, locked: Boolean)

    /** Locks or unlocks a location; the dispatcher sends no vehicle to a locked location. */
    public suspend fun setLocationLocked(location: String, locked: Boolean)

    /** Rebuilds the routing graphs (after path properties or locks changed). */
    public suspend fun updateRoutingTopology()

    /**
     * Replaces the whole plant with [model], as openTCS's model upload does. Final transport orders and finished
     * order sequences are dropped; the vehicles of [model] start afresh, with drivers attached and enabled as at
     * start-up. Clients learn of it through a [org.ktcs.api.event.PlantModelReplacedEvent].
     *
     * @throws org.ktcs.api.error.IllegalStateChangeException while a transport order is not final, an order
     *   sequence is not finished or a vehicle is still moving (the message names them).
     * @throws org.ktcs.api.error.InvalidRequestException if [model] has errors (the message lists them).
     */
    public suspend fun replacePlantModel(model: PlantModel)
}
