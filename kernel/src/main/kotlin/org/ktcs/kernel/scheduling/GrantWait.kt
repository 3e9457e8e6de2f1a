package org.ktcs.kernel.scheduling

/** Why a client's oldest pending request is not granted yet ([DefaultScheduler.grantWaitOf]). */
enum class GrantWait(val label: String) {
    /** It asks for nothing: it drives, operates or waits for something else than the scheduler. */
    NONE_PENDING("none_pending"),

    /** Its client is paused. */
    PAUSED("paused"),

    /** Another client holds a resource it asks for (or a block it may not enter yet). */
    OCCUPIED("occupied"),

    /** The resources are free, but the grant would close a cycle of waiting vehicles (the local rule). */
    LOCAL_RULE("local_rule"),

    /**
     * It would come into a two-way corridor towards a dead-end station stub beside it that another vehicle stands in:
     * it waits outside until the stub is free, since that vehicle may have to leave the way it would come.
     */
    STATION_TAKEN("station_taken"),

    /** The resources are free and the local rule allows it, but the park test refused it (within its patience). */
    PARK_TEST("park_test"),
}
