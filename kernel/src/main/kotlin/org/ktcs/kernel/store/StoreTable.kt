package org.ktcs.kernel.store

/** The store's tables: each holds one row per object, keyed by its name, with the object as JSON. */
enum class StoreTable(val sqlName: String) {
    TRANSPORT_ORDERS("transport_orders"),
    ORDER_SEQUENCES("order_sequences"),
    VEHICLES("vehicles"),
    PLANT_LOCKS("plant_locks"),
    NOTIFICATIONS("notifications"),
    KERNEL_VALUES("kernel_values"),
}

/** One change for the store: the row [name] of [table] becomes [value] (serialised by [StateCodec]), or goes. */
sealed interface StoreChange {
    val table: StoreTable

    /** The row it changes; empty for a change of the whole table. */
    val rowName: String get() = (this as? Put)?.name ?: (this as? Delete)?.name ?: ""

    data class Put(override val table: StoreTable, val name: String, val value: Any) : StoreChange

    data class Delete(override val table: StoreTable, val name: String) : StoreChange

    /** Removes every row of [table] (its objects went with a replaced plant model). */
    data class Clear(override val table: StoreTable) : StoreChange
}

/** The store cannot be used: what is wrong and what the user can do about it, in [message]. */
class StoreException(message: String, cause: Throwable? = null) : RuntimeException(message, cause)
