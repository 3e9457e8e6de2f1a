package org.ktcs.kernel.web.v1.events

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import java.time.Clock
import java.time.Instant

/**
 * The most recent status messages for `GET /events` (openTCS's long polling): one per transport-order and vehicle
 * change, numbered from 0, at most [capacity] (openTCS: servicewebapi.statusEventsCapacity, 1000). Thread-safe: fed
 * by one collector of the kernel's events, read by any number of requests.
 */
class StatusEventBuffer(private val capacity: Int = 1000, private val clock: Clock = Clock.systemUTC()) {
    /** An event kept with its number and time; it becomes a status message only when a client asks for it. */
    private class Entry(val sequenceNumber: Long, val createdAt: Instant, val event: KernelEvent)

    private val entries = ArrayDeque<Entry>()
    private var nextSequenceNumber = 0L
    private val newest = MutableStateFlow(-1L)

    fun add(event: KernelEvent) {
        val isStatus = (event is TransportOrderEvent && event.current != null) ||
            (event is VehicleEvent && event.current != null)
        if (!isStatus) return
        val sequence = synchronized(this) {
            val sequence = nextSequenceNumber++
            if (entries.size == capacity) entries.removeFirst()
            entries.addLast(Entry(sequence, clock.instant(), event))
            sequence
        }
        newest.value = sequence
    }

    /** The messages numbered [min]..[max], waiting up to [timeoutMillis] for the first one if there is none yet. */
    suspend fun await(min: Long, max: Long, timeoutMillis: Long): List<StatusMessage> {
        between(min, max).takeIf { it.isNotEmpty() }?.let { return it }
        withTimeoutOrNull(timeoutMillis) { newest.first { it >= min } }
        return between(min, max)
    }

    private fun between(min: Long, max: Long): List<StatusMessage> = synchronized(this) {
        entries.filter { it.sequenceNumber in min..max }
    }.map { it.toStatusMessage() }

    private fun Entry.toStatusMessage(): StatusMessage = when (event) {
        is TransportOrderEvent -> event.current!!.toStatusMessage(sequenceNumber, createdAt)
        is VehicleEvent -> event.current!!.toStatusMessage(sequenceNumber, createdAt)
        else -> error("only order and vehicle events are kept")
    }
}
