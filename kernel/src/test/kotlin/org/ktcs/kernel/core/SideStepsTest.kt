package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point

class SideStepsTest : FunSpec({
    // An aisle A1 - A2 - A3 - A4 (two-way) with a dead-end stub A2 - S, and a one-way exit A4 -> X.
    fun twoWay(from: String, to: String) = Path("$from --- $to", from, to, maxReverseVelocity = 1000)
    val plant = PlantModel(
        "aisle with a stub",
        points = listOf("A1", "A2", "A3", "A4", "S", "X").map(::Point),
        paths = listOf(
            twoWay("A1", "A2"),
            twoWay("A2", "A3"),
            twoWay("A3", "A4"),
            twoWay("A2", "S"),
            Path("A4 --- X", "A4", "X"),
        ),
    )

    test("offers the free points up to four paths away, nearest first, in the directions paths allow") {
        SideSteps().near(plant, "A2", held = { false }) shouldBe listOf("A1", "A3", "S", "A4", "X")
        SideSteps().near(plant, "A4", held = { false }) shouldBe listOf("A3", "X", "A2", "A1", "S")
    }

    test("neither offers nor passes a held point: the vehicle in the stub's way out stays out of the way") {
        SideSteps().near(plant, "A2", held = { it == "A3" || it == "S" }) shouldBe listOf("A1")
    }

    // Head-on in the aisle: the vehicle at A4 backs off along the other's way (A3, A2) into the stub or to A1.
    test("passes a point another vehicle of the deadlock needs but does not stop on it") {
        val needed = setOf("A3", "A2")
        SideSteps().near(plant, "A4", held = { false }, needed = needed::contains) shouldBe listOf("X", "A1", "S")
    }

    // Standing on A3 or A4 would hold the whole block, in the way of every vehicle crossing it.
    test("passes the points of a single-vehicle block but does not stop on them") {
        val block = Block("Square", BlockType.SINGLE_VEHICLE_ONLY, setOf("A3", "A4", "A3 --- A4"))
        SideSteps().near(plant.copy(blocks = listOf(block)), "A2", held = { false }) shouldBe listOf("A1", "S", "X")
    }

    test("a side step a vehicle took is not offered to it again until the memory has passed, nor kept longer") {
        val taken = TakenSideSteps(memoryChecks = 60)
        taken.add("V1", "S", check = 10)

        taken.isRecent("V1", "S", check = 11) shouldBe true
        taken.isRecent("V1", "S", check = 69) shouldBe true
        taken.isRecent("V1", "A1", check = 11) shouldBe false // another point for the same vehicle
        taken.isRecent("V2", "S", check = 11) shouldBe false // the same point for another vehicle
        taken.isRecent("V1", "S", check = 70) shouldBe false

        taken.forgetOld(check = 70)
        taken.add("V1", "A1", check = 70)
        taken.forgetOld(check = 129)
        taken.isRecent("V1", "A1", check = 129) shouldBe true
        taken.isRecent("V1", "S", check = 11) shouldBe false // forgotten: asked as of an earlier check, it is gone
    }
})
