package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

class RouteCacheTest : FunSpec({
    test("the route cache asks the router once per vehicle and order, and once per vehicle and point") {
        val context = FakeDispatchContext(plant())
        val cache = RouteCache(context.router)
        val vehicle = vehicle("V1")

        repeat(2) { cache.route(vehicle, order("T1")) }
        repeat(2) { cache.costs(vehicle, "H") }
        cache.costs(vehicle.copy(currentPosition = "B"), "H")

        context.router.routeOrderCalls shouldBe 1
        context.router.routesCalls shouldBe 2
    }
})
