package org.ktcs.kernel.orders

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.events.EventBus

/**
 * The transport orders the kernel knows, and the one place where they change: [transition] for the state, [update]
 * for everything else. Every change is published as a [TransportOrderEvent] with the previous and current order.
 * Confined to the kernel context.
 */
class TransportOrderPool(private val events: EventBus, private val clock: KernelClock) : TransportOrders {
    private val orders = LinkedHashMap<String, TransportOrder>()

    override fun get(name: String): TransportOrder? = orders[name]

    override fun require(name: String): TransportOrder =
        orders[name] ?: throw ObjectUnknownException("unknown transport order '$name'")

    override fun all(): Collection<TransportOrder> = orders.values

    override fun contains(name: String): Boolean = name in orders

    /** Puts back an order of a previous run as it was, without an event (before the kernel starts). */
    fun restore(order: TransportOrder) {
        events.assertConfined { "TransportOrderPool.restore" }
        orders[order.name] = order
    }

    fun add(order: TransportOrder): TransportOrder {
        events.assertConfined { "TransportOrderPool.add" }
        if (order.name in orders) throw ObjectExistsException("transport order '${order.name}' exists already")
        val created = order.copy(history = order.history + HistoryEntry(clock.now(), HistoryCodes.ORDER_CREATED))
        orders[created.name] = created
        events.publish(TransportOrderEvent(null, created))
        return created
    }

    /** Moves the order to [to] if the life cycle allows it; otherwise throws [IllegalStateChangeException]. */
    fun transition(name: String, to: TransportOrderState, supplement: String = ""): TransportOrder {
        events.assertConfined { "TransportOrderPool.transition" }
        val order = require(name)
        if (!TransportOrderTransitions.isAllowed(order.state, to)) {
            throw IllegalStateChangeException("illegal transition ${order.state} -> $to for transport order '$name'")
        }
        val now = clock.now()
        val reachedFinal = HistoryEntry(now, HistoryCodes.ORDER_REACHED_FINAL_STATE, supplement.ifEmpty { to.name })
        val history = if (to.isFinal) order.history + reachedFinal else order.history
        return replace(order, order.copy(state = to, finishedTime = if (to.isFinal) now else null, history = history))
    }

    /** Adds a history entry with [code] and [supplement], stamped now, to order [name]. */
    fun addHistory(name: String, code: String, supplement: String): TransportOrder =
        update(name) { it.copy(history = it.history + HistoryEntry(clock.now(), code, supplement)) }

    /** Changes anything but the state. */
    fun update(name: String, change: (TransportOrder) -> TransportOrder): TransportOrder {
        events.assertConfined { "TransportOrderPool.update" }
        val order = require(name)
        val changed = change(order)
        check(changed.state == order.state && changed.name == order.name) {
            "update() must not change the state or name of '$name'; use transition()"
        }
        return if (changed == order) order else replace(order, changed)
    }

    /** Removes final orders that finished before [cutoffMillis] (epoch milliseconds); returns their names. */
    fun removeFinishedBefore(cutoffMillis: Long): List<String> = removeFinal {
        (it.finishedTime?.toEpochMilli() ?: Long.MAX_VALUE) < cutoffMillis
    }

    /** Removes every final order that [selected] picks (all of them by default). */
    fun removeFinal(selected: (TransportOrder) -> Boolean = { true }): List<String> {
        events.assertConfined { "TransportOrderPool.removeFinal" }
        val old = orders.values.filter { it.state.isFinal && selected(it) }
        old.forEach { order ->
            orders.remove(order.name)
            events.publish(TransportOrderEvent(order, null))
        }
        return old.map { it.name }
    }

    private fun replace(previous: TransportOrder, current: TransportOrder): TransportOrder {
        orders[current.name] = current
        events.publish(TransportOrderEvent(previous, current))
        return current
    }
}
