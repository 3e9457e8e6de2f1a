package org.ktcs.kernel.routing

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Link
import org.ktcs.api.model.Path
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.VehicleOrientation

class DefaultRouterTest : FunSpec({
    val detour =
        plant(path("A", "B"), path("B", "D"), path("A", "D", length = 5000), path("A", "C"), path("C", "D", 1500))

    test("routes along the shortest total distance") {
        val route = routerFor(detour).route("A", "D").shouldNotBeNull()

        route.points shouldContainExactly listOf("A", "B", "D")
        route.costs shouldBe 2000
        route.steps.map { it.routeIndex } shouldContainExactly listOf(0, 1)
    }

    test("drives a reverse-only path backward") {
        val model = plant(path("B", "A", maxVelocity = 0, maxReverseVelocity = 500))

        val route = routerFor(model).route("A", "B").shouldNotBeNull()

        route.steps shouldContainExactly listOf(Step("B --- A", "A", "B", VehicleOrientation.BACKWARD, 0))
    }

    test("never drives a direction whose maximum velocity is 0") {
        val router = routerFor(plant(path("A", "B", maxVelocity = 0, maxReverseVelocity = 0), path("B", "C")))

        router.routes(vehicle(), "A", "B").shouldBeEmpty()
        router.routes(vehicle(), "B", "A").shouldBeEmpty()
        router.routes(vehicle(), "C", "B").shouldBeEmpty()
    }

    test("avoids a locked path and uses it again once unlocked") {
        val router = routerFor(detour.copy(paths = detour.paths.map { it.copy(locked = it.name == "A --- B") }))
        router.route("A", "D").shouldNotBeNull().points shouldContainExactly listOf("A", "C", "D")

        router.updateTopology(detour)

        router.route("A", "D").shouldNotBeNull().points shouldContainExactly listOf("A", "B", "D")
    }

    test("a route from a point to itself is one step without a path at no cost") {
        routerFor(detour).route("B", "B") shouldBe Route(listOf(Step(null, null, "B", VehicleOrientation.UNDEFINED)), 0)
    }

    test("returns up to maxRoutes distinct routes, cheapest first") {
        val routes = routerFor(detour).routes(vehicle(), "A", "D", maxRoutes = 5)

        routes.map { it.points } shouldContainExactly
            listOf(listOf("A", "B", "D"), listOf("A", "C", "D"), listOf("A", "D"))
        routes.map { it.costs } shouldContainExactly listOf(2000L, 2500L, 5000L)
    }

    test("tells parallel paths between the same points apart") {
        val parallel = plant(path("A", "B", length = 300), Path("A --- B again", "A", "B", length = 200))

        routerFor(parallel).routes(vehicle(), "A", "B", maxRoutes = 3).map { it.paths } shouldContainExactly
            listOf(listOf("A --- B again"), listOf("A --- B"))
    }

    test("computes no more routes than the route computation limit") {
        val router = routerFor(detour, RouterConfiguration(routeComputationLimit = 2))

        router.routes(vehicle(), "A", "D", maxRoutes = 3).map { it.costs } shouldContainExactly listOf(2000L, 2500L)
    }

    test("rejects asking for fewer than one route") {
        shouldThrow<IllegalArgumentException> { routerFor(detour).routes(vehicle(), "A", "D", maxRoutes = 0) }
    }

    test("finds no route to or from unknown points, nor before a topology is known") {
        routerFor(detour).routes(vehicle(), "A", "Nowhere").shouldBeEmpty()
        routerFor(detour).routes(vehicle(), "Nowhere", "A").shouldBeEmpty()
        DefaultRouter(RouterConfiguration()).routes(vehicle(), "A", "D").shouldBeEmpty()
    }

    test("avoids the points, paths and locations' linked points it is told to avoid") {
        val model = detour.copy(locations = listOf(station("Station", Link("C"))))
        val router = routerFor(model)

        router.routes(vehicle(), "A", "D", setOf("B")).single().points shouldContainExactly listOf("A", "C", "D")
        router.routes(vehicle(), "A", "D", setOf("A --- B")).single().points shouldContainExactly listOf("A", "C", "D")
        router.routes(vehicle(), "A", "D", setOf("B", "Station")).single().points shouldContainExactly listOf("A", "D")
        router.routes(vehicle(), "A", "D", setOf("B", "Station", "A --- D")).shouldBeEmpty()
    }

    test("every algorithm finds a route of the same cost") {
        RoutingAlgorithm.entries.forEach { algorithm ->
            val route = routerFor(detour, RouterConfiguration(algorithm = algorithm)).route("A", "D")

            route?.costs shouldBe 2000
        }
    }

    test("a route around an avoided point is found with every algorithm") {
        RoutingAlgorithm.entries.forEach { algorithm ->
            val router = routerFor(detour, RouterConfiguration(algorithm = algorithm))

            router.routes(vehicle(), "A", "D", setOf("B")).single().costs shouldBe 2500
            router.route("A", "D")?.costs shouldBe 2000
        }
    }

    test("never avoids the start point, but finds no route to an avoided destination") {
        val router = routerFor(detour)

        router.routes(vehicle(), "A", "D", setOf("A")).single().points shouldContainExactly listOf("A", "B", "D")
        router.routes(vehicle(), "A", "D", setOf("D")).shouldBeEmpty()
    }
})
