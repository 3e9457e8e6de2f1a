package org.ktcs.kernel.store

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.LocationEvent
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.PathEvent
import org.ktcs.api.event.PlantModelReplacedEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.UserNotificationEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.kernel.core.KernelCore

/**
 * Turns the kernel's events into store changes, in the kernel context: the journal's one hook into the kernel.
 * Per event it does work for the one object that changed (no scans); a vehicle is written only when something
 * the store keeps of it changed, not on every movement.
 */
class StateRecorder(private val core: KernelCore, private val journal: StateJournal, notificationsSoFar: Long) {
    private var notificationNumber = notificationsSoFar
    private val vehiclesWritten = HashMap<String, StoredVehicle>()
    private var namesWritten: NamePosition? = null

    fun onEvent(event: KernelEvent) {
        when (event) {
            is TransportOrderEvent -> record(StoreTable.TRANSPORT_ORDERS, event.previous, event.current) { it.name }

            is OrderSequenceEvent -> record(StoreTable.ORDER_SEQUENCES, event.previous, event.current) { it.name }

            is VehicleEvent -> event.current?.let { recordVehicle(StoredVehicle.of(it, driverOf(it.name))) }

            is PathEvent -> event.current?.let { lock(it.name, StoredLock(StoredLock.PATH, it.locked)) }

            is LocationEvent -> event.current?.let { lock(it.name, StoredLock(StoredLock.LOCATION, it.locked)) }

            is UserNotificationEvent -> journal.append(
                StoreChange.Put(
                    StoreTable.NOTIFICATIONS,
                    StateStore.notificationKey(++notificationNumber),
                    event.notification,
                ),
            )

            is PlantModelReplacedEvent -> {
                vehiclesWritten.clear()
                journal.append(StoreChange.Clear(StoreTable.VEHICLES))
                journal.append(StoreChange.Clear(StoreTable.PLANT_LOCKS))
            }

            else -> Unit
        }
    }

    /** An order or sequence changed: its row becomes [current], or goes with it; a new one moves the names on. */
    private fun <T : Any> record(table: StoreTable, previous: T?, current: T?, name: (T) -> String) {
        if (current == null) {
            journal.append(StoreChange.Delete(table, name(previous!!)))
            return
        }
        journal.append(StoreChange.Put(table, name(current), current))
        if (previous == null) recordNames()
    }

    /** Writes every vehicle as it is now (after a restart put back what the store had). */
    fun recordAllVehicles() {
        core.plant.vehicles().forEach { recordVehicle(StoredVehicle.of(it, driverOf(it.name))) }
    }

    private fun recordVehicle(stored: StoredVehicle) {
        if (vehiclesWritten[stored.name] == stored) return
        vehiclesWritten[stored.name] = stored
        journal.append(StoreChange.Put(StoreTable.VEHICLES, stored.name, stored))
    }

    private fun driverOf(vehicle: String): String? =
        runCatching { core.controllers.driverName(vehicle) }.getOrNull()

    private fun lock(name: String, lock: StoredLock) {
        journal.append(StoreChange.Put(StoreTable.PLANT_LOCKS, name, lock))
    }

    /** The name generator's position, when it moved: an order named by its client leaves it where it was. */
    private fun recordNames() {
        val position = NamePosition(core.names.lastMillisUsed, core.names.lastCounterUsed)
        if (position == namesWritten) return
        namesWritten = position
        journal.append(StoreChange.Put(StoreTable.KERNEL_VALUES, NAMES_KEY, position))
    }

    companion object {
        const val NAMES_KEY = "nameGenerator"
    }
}
