package org.ktcs.kernel.web.v1.events

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import java.time.Clock

/**
 * The most recent status messages for `GET /events` (openTCS's long polling): one per transport-order and vehicle
 * change, numbered from 0, at most [capacity] (openTCS: servicewebapi.statusEventsCapacity, 1000). Thread-safe: fed
 * by one collector of the kernel's events, read by any number of requests.
 */
class StatusEventBuffer(private val capacity: Int = 1000, private val clock: Clock = Clock.systemUTC()) {
    private val messages = ArrayDeque<StatusMessage>()
    private var nextSequenceNumber = 0L
    private val newest = MutableStateFlow(-1L)

    fun add(event: KernelEvent) {
        val message = synchronized(this) {
            val sequence = nextSequenceNumber
            val message = when (event) {
                is TransportOrderEvent -> event.current?.toStatusMessage(sequence, clock.instant())
                is VehicleEvent -> event.current?.toStatusMessage(sequence, clock.instant())
                else -> null
            } ?: return
            nextSequenceNumber++
            if (messages.size == capacity) messages.removeFirst()
            messages.addLast(message)
            message
        }
        newest.value = message.sequenceNumber
    }

    /** The messages numbered [min]..[max], waiting up to [timeoutMillis] for the first one if there is none yet. */
    suspend fun await(min: Long, max: Long, timeoutMillis: Long): List<StatusMessage> {
        between(min, max).takeIf { it.isNotEmpty() }?.let { return it }
        withTimeoutOrNull(timeoutMillis) { newest.first { it >= min } }
        return between(min, max)
    }

    private fun between(min: Long, max: Long): List<StatusMessage> = synchronized(this) {
        messages.filter { it.sequenceNumber in min..max }
    }
}
