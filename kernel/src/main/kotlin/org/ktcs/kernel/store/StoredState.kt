package org.ktcs.kernel.store

import org.ktcs.api.event.UserNotification
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder

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
            fun <T> read(table: StoreTable, parse: (String) -> T): List<Pair<String, T>> {
                val parsed = ArrayList<Pair<String, T>>()
                // Each chunk parsed on all cores: reading 100,000 orders is most of a restart's work.
                store.rows(table) { chunk ->
                    chunk.parallelStream().map { (name, json) -> name to parseRow(store, table, name, json, parse) }
                        .forEachOrdered(parsed::add)
                }
                return parsed
            }
            return StoredState(
                orders = read(StoreTable.TRANSPORT_ORDERS, StateCodec::order).map { it.second }
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
