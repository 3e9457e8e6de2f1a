package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.simulation.TrafficGrid
import kotlin.random.Random

/**
 * [ParkGuard] keeps standings and refusals from test to test: on random fleets on a traffic grid, changed one vehicle
 * at a time while the same grants are asked for again and again (as the scheduler retries the grants it held back),
 * it must answer exactly as the park test run from scratch on the whole fleet.
 */
class ParkGuardIncrementalTest : FunSpec({
    val model = TrafficGrid(4, 4, 3).build()
    val points = model.points.map { it.name }
    val successors = model.paths.groupBy({ it.sourcePoint }, { it.destinationPoint })

    test("the incremental guard answers every grant and retreat as the test from scratch does") {
        var refused = 0
        var allowed = 0
        for (seed in 1..100) {
            val fleet =
                RandomFleet(Random(seed), points, successors, blockPoints = points.shuffled(Random(seed)).take(4))
            val guard = ParkGuard(ParkSafety(model), { fleet.holds.keys }, fleet::holdingsOf, fleet.fronts::get) {
                it in fleet.blockPoints
            }
            val scratch = ScratchPark(ParkSafety(model), fleet)
            repeat(400) {
                fleet.changeOne { client ->
                    fleet.asks[client]?.let { scratch.mayGrant(client, it.first, it.second) } ?: false
                }
                    ?.let(guard::changed)
                for ((client, ask) in fleet.asks) {
                    val (point, heldAfter) = ask
                    val expected = scratch.mayGrant(client, point, heldAfter)
                    guard.mayGrant(client, point, heldAfter) shouldBe expected
                    if (expected) allowed++ else refused++
                    guard.retreatPoint(client) shouldBe scratch.retreatPoint(client)
                }
            }
        }
        refused shouldBeGreaterThan 200
        allowed shouldBeGreaterThan 10_000
    }
})

/** Up to 4 vehicles, one more than the grid's park points (so the test is sometimes off), moved at random. */
private class RandomFleet(
    private val random: Random,
    private val points: List<String>,
    private val successors: Map<String, List<String>>,
    val blockPoints: List<String>,
) {
    val holds = HashMap<String, Set<String>>()
    val fronts = HashMap<String, String>()

    // Per vehicle, the grant it keeps asking for: the point it would end at and what it would hold then.
    val asks = HashMap<String, Pair<String, Set<String>>>()

    fun holdingsOf(client: String): Set<String> = holds[client].orEmpty()

    // Changes one vehicle or what it asks for; returns its name if what it holds or its front changed. Mostly a
    // vehicle drives the step it asked for if [allowed] (as the scheduler grants), sometimes whether or not.
    fun changeOne(allowed: (String) -> Boolean): String? {
        val client = "v${random.nextInt(4)}"
        val ask = asks[client]
        when (random.nextInt(10)) {
            0 -> holds.remove(client).also { fronts.remove(client) }

            1 -> place(client)

            in 2..6 -> if (ask != null && (
                    random.nextInt(
                        40,
                    ) == 0 || allowed(client)
                    )
            ) {
                drive(client, ask)
            } else {
                return null
            }

            7 -> holds[client] = fronts[client]?.let { setOf(it) } ?: return null

            8 -> holds[client] = (holds[client] ?: return null) + points.random(random)

            else -> return null.also { ask(client) }
        }
        return client
    }

    // Drives [client] the step it asked for, still holding where it came from (until it frees it).
    private fun drive(client: String, ask: Pair<String, Set<String>>) {
        holds[client] = ask.second + listOfNotNull(fronts[client])
        fronts[client] = ask.first
        ask(client)
    }

    // Puts [client] on a random point, holding up to two more points behind or beside it.
    private fun place(client: String) {
        val front = points.random(random)
        val extra = if (random.nextInt(4) == 0) listOf(points.random(random)) else emptyList()
        holds[client] = setOf(front) + extra + "path-$front"
        if (random.nextInt(5) > 0) fronts[client] = front else fronts.remove(client)
    }

    // Makes [client] ask to drive on to a successor of where it stands (or anywhere).
    private fun ask(client: String) {
        val from = fronts[client]
        val next = from?.let { successors[it] }?.takeIf { it.isNotEmpty() }?.random(random) ?: points.random(random)
        val behind = if (from != null && random.nextBoolean()) setOf(from) else emptySet()
        asks[client] = next to behind + next + "path-$next"
    }
}

/** The park test as it ran before it kept anything: the whole fleet rebuilt for every question. */
private class ScratchPark(private val parks: ParkSafety, private val fleet: RandomFleet) {
    fun mayGrant(client: String, point: String, heldAfter: Set<String>): Boolean {
        val at = parks.pointIndex(point).takeIf { it >= 0 } ?: return true
        return standings(standing(client, at, heldAfter))?.let(parks::isSafe) ?: true
    }

    fun retreatPoint(client: String): String? {
        val all = standings(null) ?: return null
        return all.firstOrNull { it.name == client }?.let { parks.retreatPoint(all, it) }
    }

    private fun standings(grantee: ParkSafety.Standing?): List<ParkSafety.Standing>? {
        val all = listOfNotNull(grantee) + fleet.holds.keys.filter { it != grantee?.name }.mapNotNull { client ->
            val holds = fleet.holdingsOf(client)
            val at = fleet.fronts[client]?.let(parks::pointIndex)?.takeIf { it >= 0 }
                ?: holds.firstNotNullOfOrNull { parks.pointIndex(it).takeIf { i -> i >= 0 } }
            at?.let { standing(client, it, holds) }
        }
        return all.takeIf { it.size <= parks.parkPoints }
    }

    private fun standing(client: String, at: Int, holds: Set<String>): ParkSafety.Standing {
        val exits = holds.filter { it in fleet.blockPoints }.map(parks::pointIndex).filter { it >= 0 && it != at }
        val points = holds.map(parks::pointIndex).filter { it >= 0 }.toIntArray()
        return ParkSafety.Standing(
            client,
            at,
            points,
            if (exits.isEmpty()) intArrayOf(at) else (exits + at).toIntArray(),
        )
    }
}
