package org.ktcs.kernel.bench

import org.ktcs.api.model.PlantModel
import kotlin.random.Random

/** One bench order: `Load cargo` at [from], `Unload cargo` at [to]. */
data class BenchOrder(val name: String, val from: String, val to: String)

/** Random bench orders on a plant: loading at one station, unloading at another, the same for the same seed. */
class BenchOrders(model: PlantModel, seed: Long) {
    private val random = Random(seed)
    private val sources = stationsAllowing(model, BenchClient.LOAD)
    private val targets = stationsAllowing(model, BenchClient.UNLOAD)

    init {
        require(sources.isNotEmpty() && targets.size >= 2) {
            "plant '${model.name}' needs locations that allow '${BenchClient.LOAD}' and at least two that allow " +
                "'${BenchClient.UNLOAD}'"
        }
    }

    /** [count] orders named [prefix] plus a number. */
    fun next(prefix: String, count: Int): List<BenchOrder> = List(count) { index ->
        val from = sources.random(random)
        BenchOrder("$prefix${index + 1}", from, targets.filter { it != from }.random(random))
    }

    private companion object {
        fun stationsAllowing(model: PlantModel, operation: String): List<String> = model.locations
            .filter { location -> model.locationType(location.type)?.allowedOperations?.contains(operation) == true }
            .filter { location ->
                location.links.any {
                    it.allowedOperations.isEmpty() ||
                        operation in it.allowedOperations
                }
            }
            .map { it.name }
    }
}
