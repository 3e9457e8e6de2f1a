package org.ktcs.kernel.routing

import io.kotest.assertions.throwables.shouldThrowWithMessage
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Link
import org.ktcs.api.model.Point

class EdgeCostsTest : FunSpec({
    val detour =
        plant(path("A", "B"), path("B", "D"), path("A", "D", length = 5000), path("A", "C"), path("C", "D", 1500))

    fun configured(vararg evaluators: EdgeEvaluator) = RouterConfiguration(edgeEvaluators = evaluators.toList())

    context("TRAVELTIME") {
        val model = plant(path("A", "B", maxVelocity = 100), path("A", "C"), path("C", "B"))
        val router = routerFor(model, configured(EdgeEvaluator.TRAVELTIME))

        test("prefers a longer but faster way, costed in milliseconds") {
            val route = router.route("A", "B").shouldNotBeNull()

            route.points shouldContainExactly listOf("A", "C", "B")
            route.costs shouldBe 2000
        }

        test("uses the lower of the vehicle's and the path's velocity") {
            val route = router.route("A", "B", vehicle(maxVelocity = 100)).shouldNotBeNull()

            route.points shouldContainExactly listOf("A", "B")
            route.costs shouldBe 10_000
        }

        test("uses reverse velocities backward and forbids driving backward at 0") {
            val reverse = routerFor(plant(path("B", "A", 1000, 0, 200)), configured(EdgeEvaluator.TRAVELTIME))

            reverse.route("A", "B", vehicle(maxReverseVelocity = 100))?.costs shouldBe 10_000
            reverse.routes(vehicle(maxReverseVelocity = 0), "A", "B").shouldBeEmpty()
        }
    }

    test("HOPS prefers the route with the fewest paths") {
        val route = routerFor(detour, configured(EdgeEvaluator.HOPS)).route("A", "D").shouldNotBeNull()

        route.points shouldContainExactly listOf("A", "D")
        route.costs shouldBe 1
    }

    test("summed evaluators add their costs up per path") {
        routerFor(detour, configured(EdgeEvaluator.DISTANCE, EdgeEvaluator.HOPS)).route("A", "D")?.costs shouldBe 2002
    }

    context("EXPLICIT_PROPERTIES") {
        val model = plant(
            path("A", "B", properties = mapOf("tcs:routingCostForward" to "5")),
            path("B", "D", properties = mapOf("tcs:routingCostForward" to "5")),
            path(
                "A",
                "D",
                properties = mapOf(
                    "tcs:routingCostForward" to "Infinity",
                    "tcs:routingCostForwardG1" to "100",
                ),
            ),
            path("D", "E", maxReverseVelocity = 1000, properties = mapOf("tcs:routingCostReverse" to "7")),
        )
        val explicit = configured(EdgeEvaluator.EXPLICIT_PROPERTIES)

        test("reads the properties of the vehicle's routing group, where Infinity forbids a path") {
            val router = routerFor(model, explicit)

            router.route("A", "D", vehicle()).shouldNotBeNull().points shouldContainExactly listOf("A", "B", "D")
            router.route("A", "D", vehicle(routingGroup = "G1"))?.costs shouldBe 100
        }

        test("charges the configured default for a direction without a property") {
            val router = routerFor(model, explicit.copy(explicitPropertiesDefaultValue = 3))

            router.route("A", "D", vehicle(routingGroup = "G1"))?.costs shouldBe 6
            router.route("D", "E")?.costs shouldBe 3
        }

        test("reads the reverse property when driving backward") {
            routerFor(model, explicit).route("E", "D")?.costs shouldBe 7
        }
    }

    context("a point linked to a location") {
        // A → S → D passes the station S; A → C → D is 1 m longer.
        val model = plant(
            path("A", "S"),
            path("S", "D"),
            path("A", "C"),
            path("C", "D", length = 2000),
            locations = listOf(station("Station", Link("S"))),
        )
        val surcharged = RouterConfiguration(operationPointSurcharge = 200)

        test("costs the surcharge (200 % by default) more to drive onto, so a passing route goes round it") {
            surcharged shouldBe RouterConfiguration()
            val route = routerFor(model).route("A", "D").shouldNotBeNull()

            route.points shouldContainExactly listOf("A", "C", "D")
            route.costs shouldBe 3000
        }

        test("is passed through with the surcharge off or smaller than the detour") {
            routerFor(model, RouterConfiguration(operationPointSurcharge = 0)).route("A", "D")?.points shouldBe
                listOf("A", "S", "D")
            routerFor(model, RouterConfiguration(operationPointSurcharge = 50)).route("A", "D")?.costs shouldBe 2500
        }

        test("charges a route ending there the surcharge on its last path") {
            routerFor(model, surcharged).route("A", "S")?.costs shouldBe 3000
        }
    }

    test("a negative surcharge is refused, naming the setting") {
        shouldThrowWithMessage<IllegalArgumentException>("operationPointSurcharge must not be negative, was -1") {
            RouterConfiguration(operationPointSurcharge = -1)
        }
    }

    test("BOUNDING_BOX keeps vehicles off points too small for them") {
        val small = BoundingBox(length = 500, width = 500)
        val model = detour.copy(
            points = detour.points.map {
                if (it.name == "B") {
                    Point("B", maxVehicleBoundingBox = small)
                } else {
                    it
                }
            },
        )
        val router = routerFor(model, configured(EdgeEvaluator.DISTANCE, EdgeEvaluator.BOUNDING_BOX))

        router.route("A", "D").shouldNotBeNull().points shouldContainExactly listOf("A", "C", "D")
        router.route("A", "D", vehicle(boundingBox = BoundingBox(400, 400, 400)))?.costs shouldBe 2000
    }

    test("vehicles share a graph unless a configured cost function tells them apart") {
        val slow = vehicle(routingGroup = "G1", maxVelocity = 10)

        RouterConfiguration().graphKeyOf(slow) shouldBe RouterConfiguration().graphKeyOf(vehicle())
        configured(EdgeEvaluator.EXPLICIT_PROPERTIES).graphKeyOf(slow).routingGroup shouldBe "G1"
        configured(EdgeEvaluator.TRAVELTIME).graphKeyOf(slow).velocities shouldBe Velocities(10, 1000)
    }

    test("cost properties are whole numbers, rounded from decimals; anything else forbids") {
        listOf("12", " 3.6 ", "-5", "Infinity", "NaN", "cheap").map(::parseCost) shouldBe
            listOf(12L, 4L, -5L, null, null, null)
    }
})
