package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.maps.shouldBeEmpty
import io.kotest.matchers.shouldBe

class DefaultSchedulerTest : FunSpec({
    test("grants free resources through the clock, holding them from the decision on") {
        val f = SchedulerFixture()
        val v1 = f.client("v1")

        f.scheduler.allocate(v1, setOf("A", "A-B"))

        v1.granted.shouldBeEmpty()
        f.held(v1) shouldBe setOf("A", "A-B")
        f.clock.drain()
        v1.granted shouldContainExactly listOf(setOf("A", "A-B"))
    }

    test("what one client holds is its entry of the allocations, a copy that later grants leave as it was") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.allocate(v2, "B")

        val held = f.scheduler.allocationsOf("v1")
        held shouldBe f.scheduler.allocations().getValue("v1")
        f.allocate(v1, "C")
        held shouldBe setOf("A")
        f.scheduler.allocationsOf("v1") shouldBe setOf("A", "C")
        f.scheduler.allocationsOf("nobody") shouldBe emptySet()
    }

    test("a request for held resources waits and is granted once they are freed") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")

        f.allocate(v2, "A", "B")
        v2.granted.shouldBeEmpty()
        f.waiting(v2) shouldContainExactly listOf(setOf("A", "B"))

        f.free(v1, "A")
        v2.granted shouldContainExactly listOf(setOf("A", "B"))
        f.scheduler.pendingAllocations().shouldBeEmpty()
    }

    test("requests waiting for the same resource are granted in request order") {
        val f = SchedulerFixture()
        val (v1, v2, v3) = listOf("v1", "v2", "v3").map(f::client)
        f.allocate(v1, "A")
        f.allocate(v3, "A")
        f.allocate(v2, "A")

        f.free(v1, "A")
        v3.granted shouldContainExactly listOf(setOf("A"))
        v2.granted.shouldBeEmpty()

        f.free(v3, "A")
        v2.granted shouldContainExactly listOf(setOf("A"))
    }

    test("a younger request for free resources is not held up by an older one that waits") {
        val f = SchedulerFixture()
        val (v1, v2, v3) = listOf("v1", "v2", "v3").map(f::client)
        f.allocate(v1, "A")
        f.allocate(v2, "A", "B")

        f.allocate(v3, "B")

        v3.granted shouldContainExactly listOf(setOf("B"))
    }

    test("a client's own requests are granted in its order") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.allocate(v2, "A")

        f.allocate(v2, "B")
        v2.granted.shouldBeEmpty()

        f.free(v1, "A")
        v2.granted shouldContainExactly listOf(setOf("A"), setOf("B"))
    }

    test("a client may request again what it already holds") {
        val f = SchedulerFixture()
        val v1 = f.client("v1")
        f.allocate(v1, "A", "A-B")

        f.allocate(v1, "A-B", "B")

        v1.granted shouldContainExactly listOf(setOf("A", "A-B"), setOf("A-B", "B"))
        f.held(v1) shouldBe setOf("A", "A-B", "B")
    }

    test("a paused client is granted nothing new until it is resumed") {
        val f = SchedulerFixture()
        val v1 = f.client("v1")
        f.scheduler.setPaused(v1, true)

        f.allocate(v1, "A")
        f.held(v1).shouldBeEmpty()
        f.waiting(v1) shouldContainExactly listOf(setOf("A"))

        f.scheduler.setPaused(v1, false)
        f.clock.drain()
        v1.granted shouldContainExactly listOf(setOf("A"))
    }

    test("resources a client refuses are freed and go to the next waiter") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        v1.accepts = false

        f.scheduler.allocate(v1, setOf("A"))
        f.allocate(v2, "A")

        f.held(v1).shouldBeEmpty()
        v2.granted shouldContainExactly listOf(setOf("A"))
    }

    test("refusing a grant keeps what the client held before it") {
        val f = SchedulerFixture()
        val v1 = f.client("v1")
        f.allocate(v1, "A")
        v1.accepts = false

        f.allocate(v1, "A", "A-B")

        f.held(v1) shouldBe setOf("A")
    }

    test("what a client frees before hearing of a grant that includes it stays its own until the grant is announced") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.allocate(v1, "A-B", "B")
        // Turning back in a dead end: the next step asks again for A, which v1 still holds, so it is granted at once.
        f.scheduler.allocate(v1, setOf("A-B", "A"))

        f.scheduler.free(v1, setOf("A"))
        f.allocate(v2, "A")

        v1.granted shouldContainExactly listOf(setOf("A"), setOf("A-B", "B"), setOf("A-B", "A"))
        f.held(v1) shouldBe setOf("A", "A-B", "B")
        v2.granted.shouldBeEmpty()
    }

    test("what a client freed before hearing of a grant it refuses is freed with it") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.scheduler.allocate(v1, setOf("A", "A-B"))
        f.scheduler.free(v1, setOf("A"))
        v1.accepts = false
        f.allocate(v2, "A")

        f.held(v1).shouldBeEmpty()
        v2.granted shouldContainExactly listOf(setOf("A"))
    }

    test("freeAll gives everything back and forgets the claim and the pending requests") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.allocate(v2, "B")
        f.allocate(v2, "A")
        f.scheduler.claim(v2, listOf(setOf("A"), setOf("C")))

        f.scheduler.freeAll(v2)
        f.free(v1, "A")

        f.scheduler.allocations() shouldBe emptyMap()
        f.scheduler.pendingAllocations().shouldBeEmpty()
        f.scheduler.claims().shouldBeEmpty()
        v2.granted shouldContainExactly listOf(setOf("B"))
    }

    test("freeAll withdraws a grant the client has not heard of yet") {
        val f = SchedulerFixture()
        val v1 = f.client("v1")
        f.scheduler.allocate(v1, setOf("A"))

        f.scheduler.freeAll(v1)
        f.clock.drain()

        v1.granted.shouldBeEmpty()
        f.scheduler.allocations().shouldBeEmpty()
    }

    test("clearPendingAllocations drops waiting requests and keeps what is held") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.allocate(v2, "B")
        f.allocate(v2, "A")

        f.scheduler.clearPendingAllocations(v2)
        f.free(v1, "A")

        f.scheduler.pendingAllocations().shouldBeEmpty()
        f.held(v2) shouldBe setOf("B")
    }

    test("claims are recorded, replaced and forgotten, and block nobody") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.scheduler.claim(v1, listOf(setOf("A"), setOf("B")))
        f.scheduler.claim(v1, listOf(setOf("B")))

        f.allocate(v2, "B")

        v2.granted shouldContainExactly listOf(setOf("B"))
        f.scheduler.claims() shouldBe mapOf("v1" to listOf(setOf("B")))
        f.scheduler.unclaim(v1)
        f.scheduler.claims().shouldBeEmpty()
    }

    test("a new plant model clears allocations, waiting requests, undelivered grants and claims") {
        val f = SchedulerFixture()
        val (v1, v2, v3) = listOf("v1", "v2", "v3").map(f::client)
        f.allocate(v1, "A")
        f.allocate(v2, "A")
        f.scheduler.claim(v1, listOf(setOf("B")))
        f.scheduler.allocate(v3, setOf("C"))

        f.scheduler.updatePlantModel(plant("A-B", "B-C"))
        f.clock.drain()

        f.scheduler.allocations().shouldBeEmpty()
        f.scheduler.pendingAllocations().shouldBeEmpty()
        f.scheduler.claims().shouldBeEmpty()
        v3.granted.shouldBeEmpty()
        f.allocate(v3, "A")
        v3.granted shouldContainExactly listOf(setOf("A"))
    }
})
