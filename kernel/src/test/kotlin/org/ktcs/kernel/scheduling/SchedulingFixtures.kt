package org.ktcs.kernel.scheduling

import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point

/**
 * A model of the paths named `SOURCE-DESTINATION` in [paths], their points, and [blocks]. [entryDirections] gives
 * paths a [BLOCK_ENTRY_DIRECTION].
 */
fun plant(
    vararg paths: String,
    blocks: List<Block> = emptyList(),
    entryDirections: Map<String, String> = emptyMap(),
): PlantModel {
    val modelPaths = paths.map { name ->
        val (source, destination) = name.split("-")
        val properties = entryDirections[name]?.let { mapOf(BLOCK_ENTRY_DIRECTION to it) }.orEmpty()
        Path(name, source, destination, properties = properties)
    }
    val points = modelPaths.flatMap { listOf(it.sourcePoint, it.destinationPoint) }.distinct().map { Point(it) }
    return PlantModel("test", points = points, paths = modelPaths, blocks = blocks)
}

fun singleVehicleBlock(name: String, vararg members: String): Block =
    Block(name, BlockType.SINGLE_VEHICLE_ONLY, members.toSet())

fun sameDirectionBlock(name: String, vararg members: String): Block =
    Block(name, BlockType.SAME_DIRECTION_ONLY, members.toSet())

/** A scheduler over [model] with its clock, and shorthand for the calls tests make most. */
class SchedulerFixture(model: PlantModel = plant("A-B", "B-C", "C-D")) {
    val clock = ManualClock()
    val scheduler = DefaultScheduler(model, clock)

    fun client(name: String): RecordingClient = RecordingClient(name)

    fun allocate(client: RecordingClient, vararg resources: String) {
        scheduler.allocate(client, resources.toSet())
        clock.drain()
    }

    fun free(client: RecordingClient, vararg resources: String) {
        scheduler.free(client, resources.toSet())
        clock.drain()
    }

    fun held(client: RecordingClient): Set<String> = scheduler.allocations()[client.name].orEmpty()

    fun waiting(client: RecordingClient): List<Set<String>> = scheduler.pendingAllocations()[client.name].orEmpty()
}
