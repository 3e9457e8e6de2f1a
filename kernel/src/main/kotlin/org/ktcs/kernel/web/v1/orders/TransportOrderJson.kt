package org.ktcs.kernel.web.v1.orders

import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.v1.V1Json
import java.lang.ref.ReferenceQueue
import java.lang.ref.WeakReference
import java.util.concurrent.ConcurrentHashMap

/**
 * Each transport order's v1 JSON, encoded once per version of the order. Orders are immutable and every change
 * replaces the pool's instance, so an entry is valid exactly while it was made from the very instance asked about;
 * listing a pool of thousands of orders then only encodes those that changed since the last request.
 *
 * An entry holds its order weakly and goes once the order is gone (a newer version replaced it, the sweep removed
 * it): a client that creates orders and never lists the whole pool must not make the cache keep every order ever
 * created.
 */
class TransportOrderJson {
    private class Entry(order: TransportOrder, val bytes: ByteArray, queue: ReferenceQueue<TransportOrder>) :
        WeakReference<TransportOrder>(order, queue) {
        val name: String = order.name
    }

    private val entries = ConcurrentHashMap<String, Entry>()
    private val collected = ReferenceQueue<TransportOrder>()

    /** [order] as `GET /transportOrders/{NAME}` answers it, UTF-8 encoded. */
    fun of(order: TransportOrder): ByteArray {
        dropCollected()
        entries[order.name]?.takeIf { it.get() === order }?.let { return it.bytes }
        val bytes = V1Json.json.encodeToString(TransportOrderDto.serializer(), order.toDto()).encodeToByteArray()
        entries[order.name] = Entry(order, bytes, collected)
        return bytes
    }

    /** Drops the entries whose orders were collected (unless a newer entry took the name meanwhile). */
    private fun dropCollected() {
        while (true) {
            val entry = collected.poll() as? Entry ?: return
            entries.remove(entry.name, entry)
        }
    }

    /**
     * The JSON array of [orders]. When they are the whole pool ([wholePool]), entries of orders no longer in it are
     * dropped, so removed orders are not kept alive by the cache.
     */
    fun list(orders: List<TransportOrder>, wholePool: Boolean): JsonArrayContent {
        val parts = orders.map(::of)
        if (wholePool && entries.size > orders.size) {
            val names = orders.mapTo(HashSet(orders.size * 2)) { it.name }
            entries.keys.retainAll(names)
        }
        return JsonArrayContent(parts)
    }

    /** How many orders are cached (for tests). */
    val size: Int get() = dropCollected().let { entries.size }
}
