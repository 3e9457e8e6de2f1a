package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe

class SingleVehicleBlockTest : FunSpec({
    val model = plant("A-B", "B-C", "C-D", blocks = listOf(singleVehicleBlock("S", "B", "B-C", "C")))

    test("a request touching a member holds the whole block, and the grant names what was asked for") {
        val f = SchedulerFixture(model)
        val v1 = f.client("v1")

        f.allocate(v1, "A-B", "B")

        f.held(v1) shouldBe setOf("A-B", "B", "B-C", "C")
        v1.granted shouldContainExactly listOf(setOf("A-B", "B"))
        f.waiting(v1).shouldBeEmpty()
    }

    test("no other client gets any member while the block is in use") {
        val f = SchedulerFixture(model)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "B")

        f.allocate(v2, "C-D", "C")

        v2.granted.shouldBeEmpty()
        f.waiting(v2) shouldContainExactly listOf(setOf("C-D", "C"))
    }

    test("the block stays held while the client holds a member it asked for") {
        val f = SchedulerFixture(model)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A-B", "B")
        f.allocate(v1, "B-C", "C")
        f.allocate(v2, "C-D", "C")

        f.free(v1, "A-B", "B")

        f.held(v1) shouldBe setOf("B", "B-C", "C")
        v2.granted.shouldBeEmpty()
    }

    test("the block goes to the next client once every member asked for is freed") {
        val f = SchedulerFixture(model)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A-B", "B")
        f.allocate(v2, "C")

        f.free(v1, "B")

        f.held(v1) shouldBe setOf("A-B")
        v2.granted shouldContainExactly listOf(setOf("C"))
        f.held(v2) shouldBe setOf("B", "B-C", "C")
    }
})
