package org.ktcs.kernel.workingset

/** Where the generation of object names stands, read-only (the state store records it). */
interface NamesUsed {
    /** The time part of the last generated name, or -1. */
    val lastMillisUsed: Long

    /** The counter of the last generated name. */
    val lastCounterUsed: Long
}
