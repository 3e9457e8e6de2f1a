package org.ktcs.kernel.scheduling

/**
 * Traffic control's timers, all in vehicle time (the kernel clock times `loopback.timeFactor`), so that a plant behaves
 * the same at any time factor: when a held-back grant counts as stuck, when its vehicle retreats, and how long the park
 * test may hold a grant back.
 */
internal object TrafficTimers {
    /** Two watchdog periods: shorter refusals are queues moving along, not vehicles stuck face to face. */
    const val HELD_BACK_REPORT_MILLIS = 2_000L

    /**
     * How long (vehicle time) a grant is held back before its vehicle retreats into a dead-end bay. Such a retreat
     * drives in and back out over the point the vehicle left, through the aisle others queue in, so it pays only
     * for a vehicle stuck for longer than a queue moving along: on the warehouse (all bays dead ends) waiting 6 s
     * instead of 2 s cut the makespan by a fifth (guide, section 12, "Session 19"). A detour bay beside a one-way
     * lane (the grids') is taken after two watchdog periods: there the retreat is a way forward.
     */
    const val DEAD_END_RETREAT_MILLIS = 6_000L

    /**
     * How long (vehicle time) the park test may hold a grant back before the local rule alone decides it. On the
     * warehouse most of the test's refusals end by this patience, not by a release, so it sets the pace there;
     * with the corridors' direction records a short one no longer lets vehicles fill an aisle from both ends
     * (guide, section 12). The grids never reach it.
     */
    const val PARK_TEST_PATIENCE_MILLIS = 3_000L

    /**
     * How long (vehicle time) a grant may be held back before the local rule alone decides it, without the dead-hole
     * check ([RouteSafety.leavesDeadHole]): a safety valve for two grants each held back for a hole the other could
     * take, or for a hole only a paused vehicle could take. The vehicle that can take a hole normally does so within a
     * step or two. It counts from the request's first refusal of any kind (counting only the wait for a dead hole was
     * tried: developer's guide, section 12, "Tried in session 29").
     */
    const val DEAD_HOLE_PATIENCE_MILLIS = 10_000L
}
