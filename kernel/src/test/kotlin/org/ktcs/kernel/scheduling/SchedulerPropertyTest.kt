package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.property.Arb
import io.kotest.property.arbitrary.bind
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.set
import io.kotest.property.checkAll
import org.ktcs.api.model.PlantModel

private val model = plant(
    "P0-P1", "P1-P2", "P2-P3", "P3-P4", "P4-P5", "P5-P4", "P4-P3", "P3-P2",
    blocks = listOf(
        singleVehicleBlock("Single", "P1", "P1-P2", "P2"),
        sameDirectionBlock("Corridor", "P3", "P4", "P3-P4", "P4-P3"),
    ),
    entryDirections = mapOf("P2-P3" to "east"),
)
private val resources = model.points.map { it.name } + model.paths.map { it.name } + "L"
private val clients = listOf("c0", "c1", "c2", "c3")

private sealed interface Step {
    val client: String
}

private data class Allocate(override val client: String, val resources: Set<String>) : Step

private data class Free(override val client: String, val resources: Set<String>) : Step

private data class FreeAll(override val client: String) : Step

private data class ClearPending(override val client: String) : Step

private data class Pause(override val client: String, val paused: Boolean) : Step

private data class Accept(override val client: String, val accepts: Boolean) : Step

private val someResources = Arb.set(Arb.element(resources), 1..3)
private val client = Arb.element(clients)
private val step: Arb<Step> = Arb.choice(
    Arb.bind(client, someResources, ::Allocate),
    Arb.bind(client, someResources, ::Allocate),
    Arb.bind(client, someResources, ::Free),
    client.map(::FreeAll),
    client.map(::ClearPending),
    Arb.bind(client, Arb.boolean(), ::Pause),
    Arb.bind(client, Arb.boolean(), ::Accept),
)

class SchedulerPropertyTest : FunSpec({
    test("random operations never break exclusivity, blocks or wake-ups") {
        checkAll(400, Arb.list(step, 1..60)) { steps ->
            val run = SchedulerRun(model, clients)
            for (step in steps) {
                run.apply(step)
                run.checkInvariants(step)
            }
            run.releaseEverything()
        }
    }
})

private class SchedulerRun(model: PlantModel, names: List<String>) {
    private val f = SchedulerFixture(model)
    private val oracle = SchedulingOracle(model)
    private val clients = names.associateWith { f.client(it) }
    private val paused = HashSet<String>()

    // What each client asked for and kept, replayed from its calls and answers: it must hold exactly that, expanded.
    private val kept = names.associateWith { HashSet<String>() }
    private val seenGrants = names.associateWith { 0 }.toMutableMap()

    fun apply(step: Step) {
        val client = clients.getValue(step.client)
        when (step) {
            is Allocate -> f.scheduler.allocate(client, step.resources)
            is Free -> f.scheduler.free(client, step.resources)
            is FreeAll -> f.scheduler.freeAll(client)
            is ClearPending -> f.scheduler.clearPendingAllocations(client)
            is Pause -> pause(client, step.paused)
            is Accept -> client.accepts = step.accepts
        }
        f.clock.drain()
        replay(step)
    }

    private fun pause(client: RecordingClient, paused: Boolean) {
        f.scheduler.setPaused(client, paused)
        if (paused) this.paused += client.name else this.paused -= client.name
    }

    private fun replay(step: Step) {
        when (step) {
            is Free -> kept.getValue(step.client) -= step.resources
            is FreeAll -> kept.getValue(step.client).clear()
            else -> Unit
        }
        for ((name, client) in clients) {
            val grants = client.granted.drop(seenGrants.getValue(name))
            seenGrants[name] = client.granted.size
            if (client.accepts) grants.forEach { kept.getValue(name) += it }
        }
    }

    // A grant deadlock avoidance holds back waits only for what others hold: once every client has given back all it
    // holds, round after round, nothing unpaused may still wait.
    fun releaseEverything() {
        repeat(clients.size + 2) {
            for (name in clients.keys) {
                apply(FreeAll(name))
                checkInvariants(FreeAll(name))
            }
        }
        val waiting = f.scheduler.pendingAllocations().filterKeys { it !in paused }
        check(waiting.isEmpty()) {
            "still waiting after every client gave back everything: $waiting, held back ${f.scheduler.heldBackClients()}"
        }
    }

    fun checkInvariants(step: Step) {
        val allocations = f.scheduler.allocations()
        val problems = oracle.sharedResources(allocations) +
            oracle.sharedSingleBlocks(allocations) +
            oracle.undirectedSharedBlocks(allocations, f.scheduler.blockDirections()) +
            oracle.unexpectedHoldings(allocations, kept) +
            oracle.lostWakeUps(
                allocations,
                f.scheduler.pendingAllocations().filterKeys { it !in f.scheduler.heldBackClients() },
                f.scheduler.blockDirections(),
                paused,
            )
        check(problems.isEmpty()) {
            "after $step: $problems\nallocations=$allocations\npending=${f.scheduler.pendingAllocations()}"
        }
    }
}
