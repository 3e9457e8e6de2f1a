package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.string.shouldStartWith
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationKernel

class TrafficChecksTest : FunSpec({
    // J is a junction (X, Y, B); B and C form a two-way dead end off it.
    fun plant(vararg stations: String) = PlantModel(
        "dead end",
        points = listOf("J", "X", "Y", "B", "C").map { Point(it) },
        paths = listOf("J" to "X", "X" to "Y", "Y" to "J", "J" to "B", "B" to "C").map { (from, to) ->
            Path("$from-$to", from, to, maxReverseVelocity = if (to in "BC") 1000 else 0)
        },
        locationTypes = listOf(LocationType("Station", setOf("NOP"))),
        locations = stations.map { Location("S-$it", "Station", links = listOf(Link(it))) },
    )

    test("a dead end with two places to stop is named with both") {
        trafficProblems(ModelIndex(plant("B", "C"))).map { it.line() } shouldContainExactly listOf(
            "WARNING point 'C': dead end C, B has 2 places to stop (location 'S-C' at C, location 'S-B' at B): " +
                "vehicles sent to two of them must pass each other on one track, which no traffic rule can " +
                "arrange; a second vehicle waits outside until the first has left",
        )
    }

    test("the kernel tells operators about such a dead end when it starts") {
        SimulationKernel(plant("B", "C"), ConfigLoader().load(null, emptyMap(), emptyList())).use { kernel ->
            kernel.core.notifications.recent().single { it.source == "traffic control" }.text shouldStartWith
                "point 'C': dead end C, B has 2 places to stop"
        }
    }

    test("one place to stop in a dead end is fine") {
        trafficProblems(ModelIndex(plant("C"))).shouldBeEmpty()
    }
})

private fun ModelProblem.line() = toString()
