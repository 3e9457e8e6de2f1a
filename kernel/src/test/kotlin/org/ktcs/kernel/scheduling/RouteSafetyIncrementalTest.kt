package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.simulation.TrafficGrid
import org.ktcs.kernel.simulation.WarehousePlant
import kotlin.random.Random

/**
 * [RouteSafety] keeps the local rule's refusals and the vehicles' look-aheads from check to check: on random fleets
 * on a traffic grid and on a warehouse, changed one step at a time (claims, grants, releases, vehicles leaving) while
 * every vehicle asks for its next step again and again (as the scheduler retries the grants it held back), it must
 * answer exactly as a check built from scratch for each question.
 */
class RouteSafetyIncrementalTest : FunSpec({
    test("on a one-way grid, the check that keeps refusals and look-aheads answers as a check from scratch does") {
        val (refused, allowed) = compareWithScratch(TrafficGrid(4, 4, 4).build(), seeds = 100)
        refused shouldBeGreaterThan 300
        allowed shouldBeGreaterThan 1_000
    }

    // Two-way aisles and dead-end stubs: look-aheads run along the aisles and end with the ways out of the stubs.
    test("on a warehouse's two-way aisles, it answers as a check from scratch does") {
        val (refused, allowed) = compareWithScratch(WarehousePlant(2, 5, 4).build(), seeds = 60)
        refused shouldBeGreaterThan 300
        allowed shouldBeGreaterThan 1_000
    }
})

// Asks every vehicle of random fleets on [model] for its next step again and again while the fleet changes one step
// at a time; returns how many grants were refused and allowed, each answer checked against a check from scratch.
private fun compareWithScratch(model: PlantModel, seeds: Int): Pair<Int, Int> {
    val exits = ExitCorridors(model)
    val pathsFrom = HashMap<String, MutableList<Pair<String, String>>>()
    for (path in model.paths) {
        if (path.maxVelocity > 0) {
            pathsFrom.getOrPut(
                path.sourcePoint,
                ::ArrayList,
            ) += path.name to path.destinationPoint
        }
        if (path.maxReverseVelocity > 0) {
            pathsFrom.getOrPut(path.destinationPoint, ::ArrayList) += path.name to path.sourcePoint
        }
    }
    var refused = 0
    var allowed = 0
    for (seed in 1..seeds) {
        val fleet = RouteFleet(Random(seed), model.points.map { it.name }, pathsFrom)
        val live = RouteSafety(exits, fleet::holdingsOf, fleet::holdersOf)
        repeat(500) {
            fleet.changeOne(live)
            for ((client, route) in fleet.routes) {
                val next = route.firstOrNull() ?: continue
                if (fleet.holdersOf(next).any { it != client }) continue
                val expected = fleet.scratch(exits).mayGrant(client, next, emptySet())
                live.mayGrant(client, next, emptySet()) shouldBe expected
                if (expected) allowed++ else refused++
            }
        }
    }
    return refused to allowed
}

/**
 * Up to [VEHICLES] vehicles on the grid, each holding the point it stands on (and, after a grant, the path and point it
 * was granted) and claiming a random way on. Every change is told to the check under test as the scheduler tells it.
 */
private class RouteFleet(
    private val random: Random,
    private val points: List<String>,
    private val pathsFrom: Map<String, List<Pair<String, String>>>,
) {
    val holds = HashMap<String, MutableSet<String>>()
    private val fronts = HashMap<String, String>()
    val routes = HashMap<String, ArrayDeque<Set<String>>>()
    private val ends = HashMap<String, String>()

    fun holdingsOf(client: String): Set<String> = holds[client].orEmpty()

    fun holdersOf(key: String): Collection<String> = holds.filterValues { key in it }.keys

    fun holdersOf(keys: Set<String>): Collection<String> = holds.filterValues { held -> keys.any { it in held } }.keys

    /** A check that has seen nothing before: every claim made again, every other vehicle standing. */
    fun scratch(exits: ExitCorridors): RouteSafety {
        val fresh = RouteSafety(exits, ::holdingsOf, ::holdersOf)
        for (client in holds.keys) {
            val route = routes[client]
            if (route == null) fresh.standing(client) else claim(fresh, client, route.toList(), ends.getValue(client))
        }
        return fresh
    }

    fun changeOne(live: RouteSafety) {
        val client = "v${random.nextInt(VEHICLES)}"
        when (random.nextInt(12)) {
            0 -> if (client in holds) leave(client, live)
            1, 2 -> if (client !in holds) place(client, live)
            3, 4 -> fronts[client]?.let { newClaim(client, it, live) }
            in 5..9 -> grantNext(client, live)
            10 -> release(client, live)
            else -> if (routes.remove(client) != null) live.unclaim(client)
        }
    }

    private fun place(client: String, live: RouteSafety) {
        val at = points.random(random)
        if (holdersOf(at).isNotEmpty()) return
        holds[client] = hashSetOf(at)
        fronts[client] = at
        live.changed(client)
        live.standing(client)
    }

    private fun leave(client: String, live: RouteSafety) {
        holds.remove(client)
        fronts.remove(client)
        routes.remove(client)
        live.remove(client)
        live.changed(client)
    }

    private fun newClaim(client: String, from: String, live: RouteSafety) {
        val route = ArrayDeque<Set<String>>()
        var at = from
        repeat(1 + random.nextInt(6)) {
            val (path, to) = pathsFrom[at]?.randomOrNull(random) ?: return@repeat
            route += setOf(path, to)
            at = to
        }
        if (route.isEmpty()) return
        routes[client] = route
        ends[client] = at
        claim(live, client, route.toList(), at)
    }

    // Grants the client its next step if nobody else holds any of it, whatever the check says: the scheduler's
    // patience and the watchdog make grants the local rule alone would not make.
    private fun grantNext(client: String, live: RouteSafety) {
        val step = routes[client]?.firstOrNull() ?: return
        if (holdersOf(step).any { it != client }) return
        holds.getOrPut(client, ::HashSet) += step
        fronts[client] = step.first { it in points }
        routes.getValue(client).removeFirst()
        live.granted(client, step)
    }

    // Gives back everything but the point the client stands on.
    private fun release(client: String, live: RouteSafety) {
        val front = fronts[client] ?: return
        holds[client] = hashSetOf(front)
        live.standing(client)
    }

    private fun claim(check: RouteSafety, client: String, route: List<Set<String>>, end: String) =
        check.claim(client, route, route.map { null }, end)
}

// Enough for the grid's directed squares to fill up, so that many grants close a cycle.
private const val VEHICLES = 11
