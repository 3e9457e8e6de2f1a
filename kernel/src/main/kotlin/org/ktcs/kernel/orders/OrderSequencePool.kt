package org.ktcs.kernel.orders

import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.OrderSequence
import org.ktcs.kernel.events.EventBus

/** The order sequences the kernel knows; every change is published. Confined to the kernel context. */
class OrderSequencePool(private val events: EventBus, private val clock: KernelClock) : OrderSequences {
    private val sequences = LinkedHashMap<String, OrderSequence>()

    override fun get(name: String): OrderSequence? = sequences[name]

    override fun require(name: String): OrderSequence =
        sequences[name] ?: throw ObjectUnknownException("unknown order sequence '$name'")

    override fun all(): Collection<OrderSequence> = sequences.values

    /** Puts back a sequence of a previous run as it was, without an event (before the kernel starts). */
    fun restore(sequence: OrderSequence) {
        events.assertConfined { "OrderSequencePool.restore" }
        sequences[sequence.name] = sequence
    }

    fun add(sequence: OrderSequence): OrderSequence {
        events.assertConfined { "OrderSequencePool.add" }
        if (sequence.name in sequences) throw ObjectExistsException("order sequence '${sequence.name}' exists already")
        val created = sequence.copy(
            history = sequence.history + HistoryEntry(clock.now(), HistoryCodes.SEQUENCE_CREATED),
        )
        sequences[created.name] = created
        events.publish(OrderSequenceEvent(null, created))
        return created
    }

    fun update(name: String, change: (OrderSequence) -> OrderSequence): OrderSequence {
        events.assertConfined { "OrderSequencePool.update" }
        val previous = require(name)
        val current = change(previous)
        if (current == previous) return previous
        sequences[name] = current
        events.publish(OrderSequenceEvent(previous, current))
        return current
    }

    /** Removes finished sequences that finished before [cutoffMillis] (epoch milliseconds). */
    fun removeFinishedBefore(cutoffMillis: Long): List<String> = removeFinished {
        (it.finishedTime?.toEpochMilli() ?: Long.MAX_VALUE) < cutoffMillis
    }

    /** Removes every finished sequence that [selected] picks (all of them by default). */
    fun removeFinished(selected: (OrderSequence) -> Boolean = { true }): List<String> {
        events.assertConfined { "OrderSequencePool.removeFinished" }
        val old = sequences.values.filter { it.finished && selected(it) }
        old.forEach {
            sequences.remove(it.name)
            events.publish(OrderSequenceEvent(it, null))
        }
        return old.map { it.name }
    }
}
