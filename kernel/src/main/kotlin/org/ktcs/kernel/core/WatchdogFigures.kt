package org.ktcs.kernel.core

/** What the deadlock watchdog has done so far (read-only; for reports and tests). */
interface WatchdogFigures {
    /** How many distinct stuck states (deadlocks) were found; one that shows as several cycles counts once. */
    val detected: Int

    /** How many deadlocks ended after the watchdog rerouted one of their vehicles. */
    val resolved: Int

    /**
     * How many vehicles held back by deadlock avoidance were sent on through a free park point (planned avoidance,
     * not a deadlock: see the developer's guide, "The traffic rule").
     */
    val retreats: Int

    /**
     * How many vehicles yielded to a fresh claim that waited, through them, for itself (planned avoidance, not a
     * deadlock: [BlockedClaims]).
     */
    val claimYields: Int

    /** How many idle vehicles were sent out of the way of waiting ones. */
    val idleVehiclesMoved: Int
}
