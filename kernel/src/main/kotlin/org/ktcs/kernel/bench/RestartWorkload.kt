package org.ktcs.kernel.bench

import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.orders.HistoryCodes
import org.ktcs.kernel.store.StateStore
import org.ktcs.kernel.store.StoreChange
import org.ktcs.kernel.store.StoreTable
import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import java.time.Instant

/**
 * `ktcs bench restart`: a state store holding [BenchOptions.storedFinal] final orders and [BenchOptions.storedOpen]
 * DISPATCHABLE ones (shaped like the demo workload's: two drive orders with routes, a history), then kTCS started
 * on it; figures: seconds until the web API answers (kTCS logs what it recovered in its output).
 */
class RestartWorkload(private val options: BenchOptions, private val figures: Figures) {
    fun run(model: PlantModel, modelFile: Path?, log: File, start: (List<String>) -> KtcsUnderTest) {
        val data = Files.createTempDirectory("ktcs-bench-restart")
        try {
            val writeStarted = System.nanoTime()
            fill(data, model)
            figures.record("store written (s)", (System.nanoTime() - writeStarted) / NANOS_PER_SECOND)
            figures.record("store size (MB)", Files.size(data.resolve(StateStore.FILE_NAME)) / BYTES_PER_MB)
            start(listOf("kernel.dataDirectory=$data", "persistence.durability=COMMIT")).use { ktcs ->
                figures.record("restart: web API answers (s)", ktcs.awaitAnswering(READY_SECONDS))
            }
        } finally {
            data.toFile().deleteRecursively()
        }
    }

    private fun fill(data: Path, model: PlantModel) {
        val orders = BenchOrders(model, options.seed)
        val steps = model.paths.take(STEPS).mapIndexed { index, path ->
            Step(path.name, path.sourcePoint, path.destinationPoint, routeIndex = index)
        }
        val now = Instant.now()
        StateStore.embedded(data, synchronous = false).use { store ->
            val all = orders.next("Stored-Final-", options.storedFinal).map { it to true } +
                orders.next("Stored-Open-", options.storedOpen).map { it to false }
            all.chunked(BATCH).forEach { batch ->
                store.write(
                    batch.map { (order, final) ->
                        StoreChange.Put(StoreTable.TRANSPORT_ORDERS, order.name, stored(order, final, steps, now))
                    },
                    flush = false,
                )
            }
        }
    }

    private fun stored(order: BenchOrder, final: Boolean, steps: List<Step>, now: Instant): TransportOrder {
        val destinations = listOf(
            Destination(order.from, BenchClient.LOAD),
            Destination(order.to, BenchClient.UNLOAD),
        )
        val created = HistoryEntry(now, HistoryCodes.ORDER_CREATED)
        return if (final) {
            TransportOrder(
                name = order.name,
                driveOrders = destinations.mapIndexed { index, destination ->
                    DriveOrder("$index", destination, Route(steps, steps.size * STEP_COST), DriveOrderState.FINISHED)
                },
                state = TransportOrderState.FINISHED,
                creationTime = now,
                finishedTime = now,
                processingVehicle = "Vehicle-01",
                currentDriveOrderIndex = 1,
                history = listOf(
                    created,
                    HistoryEntry(now, HistoryCodes.ORDER_ASSIGNED, "Vehicle-01"),
                    HistoryEntry(now, HistoryCodes.ORDER_REACHED_FINAL_STATE, "FINISHED"),
                ),
            )
        } else {
            TransportOrder(
                name = order.name,
                driveOrders = destinations.mapIndexed { index, destination -> DriveOrder("$index", destination) },
                state = TransportOrderState.DISPATCHABLE,
                creationTime = now,
                history = listOf(created),
            )
        }
    }

    private companion object {
        const val STEPS = 8
        const val STEP_COST = 5_000L
        const val BATCH = 5_000
        const val READY_SECONDS = 120L
        const val NANOS_PER_SECOND = 1e9
        const val BYTES_PER_MB = 1_048_576.0
    }
}
