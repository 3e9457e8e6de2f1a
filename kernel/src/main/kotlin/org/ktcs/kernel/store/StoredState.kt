package org.ktcs.kernel.store

import org.ktcs.api.event.UserNotification
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import java.util.concurrent.Callable
import java.util.concurrent.ExecutionException
import java.util.concurrent.ExecutorService
import java.util.concurrent.Executors
import java.util.concurrent.Future

/** Everything the store held when kTCS started, read and checked before the kernel starts. */
data class StoredState(
    val orders: List<TransportOrder>,
    val sequences: List<OrderSequence>,
    val vehicles: List<StoredVehicle>,
    val locks: Map<String, StoredLock>,
    val notifications: List<Pair<Long, UserNotification>>,
    val names: NamePosition?,
) {
    val isEmpty: Boolean get() = orders.isEmpty() && sequences.isEmpty() && vehicles.isEmpty() && locks.isEmpty()

    companion object {
        private const val CHUNKS_AHEAD = 8

        private fun <T> parseRow(
            store: StateStore,
            table: StoreTable,
            name: String,
            json: String,
            parse: (String) -> T,
        ): T =
            try {
                parse(json)
            } catch (error: Exception) {
                throw StoreException(
                    "${store.description}: row '$name' of table ${table.sqlName} cannot be read " +
                        "(${error.message?.lines()?.first()}); ${StateStore.RECOVER}",
                    error,
                )
            }

        /** Reads [store]; a row that cannot be read stops the start with a [StoreException] naming it. */
        fun load(store: StateStore): StoredState {
            val decoders = Executors.newFixedThreadPool(Runtime.getRuntime().availableProcessors()) { task ->
                Thread(task, "ktcs-store-decoder").apply { isDaemon = true }
            }
            try {
                return load(store, decoders)
            } finally {
                decoders.shutdownNow()
            }
        }

        private fun load(store: StateStore, decoders: ExecutorService): StoredState {
            // Reading rows is one thread's work, decoding their JSON most of a restart's: the chunks are decoded on
            // all cores while the next ones are read, at most a few chunks ahead (the JSON of 100,000 orders is
            // several times the size of the orders, and must not be held all at once).
            fun <T> read(table: StoreTable, parse: (String) -> T): List<Pair<String, T>> {
                val parsed = ArrayList<Pair<String, T>>()
                val pending = ArrayDeque<Future<List<Pair<String, T>>>>()
                fun takeOldest() = try {
                    parsed += pending.removeFirst().get()
                } catch (error: ExecutionException) {
                    throw error.cause ?: error
                }
                store.rows(table) { chunk ->
                    pending += decoders.submit(
                        Callable { chunk.map { (name, json) -> name to parseRow(store, table, name, json, parse) } },
                    )
                    while (pending.size > CHUNKS_AHEAD) takeOldest()
                }
                while (pending.isNotEmpty()) takeOldest()
                return parsed
            }
            return StoredState(
                orders = read(StoreTable.TRANSPORT_ORDERS, StateCodec.orders()).map { it.second }
                    .sortedWith(compareBy({ it.creationTime }, { it.name })),
                sequences = read(StoreTable.ORDER_SEQUENCES, StateCodec::sequence).map { it.second }
                    .sortedWith(compareBy({ it.creationTime }, { it.name })),
                vehicles = read(StoreTable.VEHICLES, StateCodec::vehicle).map { it.second },
                locks = read(StoreTable.PLANT_LOCKS, StateCodec::lock).toMap(),
                notifications = read(StoreTable.NOTIFICATIONS, StateCodec::notification)
                    .map { (name, notification) -> name.toLong() to notification }.sortedBy { it.first },
                names = read(StoreTable.KERNEL_VALUES) { it }.toMap()[StateRecorder.NAMES_KEY]?.let(StateCodec::names),
            )
        }
    }
}
