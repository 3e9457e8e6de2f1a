package org.ktcs.kernel.orders

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldHaveLength
import io.kotest.matchers.string.shouldStartWith
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.KernelException
import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.context.VirtualTimeKernelContext
import org.ktcs.kernel.workingset.ObjectNames

class TransportOrderFactoryTest : FunSpec({
    val model = PlantModel(
        "m",
        points = listOf(Point("A"), Point("B")),
        paths = listOf(Path("A --- B", "A", "B", 1000, maxReverseVelocity = 1000)),
        locationTypes = listOf(LocationType("Station", setOf("Load cargo", "Unload cargo"))),
        locations = listOf(Location("S", "Station", links = listOf(Link("B", setOf("Load cargo"))))),
    )
    val clock = VirtualTimeKernelContext()
    val factory = TransportOrderFactory(clock, ObjectNames(clock))

    fun create(creation: TransportOrderCreation, taken: Set<String> = emptySet()) =
        factory.create(creation, model, { it in taken }, { it == "Existing" }, { null })

    fun refusal(vararg destinations: Destination): KernelException =
        shouldThrow<KernelException> { create(TransportOrderCreation("T", destinations.toList())) }

    test("a valid order is RAW with one drive order per destination") {
        val order =
            create(TransportOrderCreation("T", listOf(Destination("S", "Load cargo"), Destination("A", "MOVE"))))
        order.driveOrders.map { it.destination.target } shouldBe listOf("S", "A")
        order.state.name shouldBe "RAW"
    }

    test("an incomplete name gets a unique suffix that sorts by creation time") {
        val first = create(
            TransportOrderCreation("Order-", listOf(Destination("A", "MOVE")), incompleteName = true),
        ).name
        val second = create(
            TransportOrderCreation("Order-", listOf(Destination("A", "MOVE")), incompleteName = true),
        ).name
        first shouldStartWith "Order-"
        first.removePrefix("Order-") shouldHaveLength 26
        (first < second) shouldBe true
    }

    test("each broken rule is refused with a message naming the problem") {
        shouldThrow<ObjectExistsException> {
            create(TransportOrderCreation("A", listOf(Destination("A", "MOVE"))), setOf("A"))
        }
            .message shouldBe "an object named 'A' exists already"
        shouldThrow<InvalidRequestException> { create(TransportOrderCreation("T", emptyList())) }
            .message shouldBe "transport order 'T' has no destinations"
        (refusal(Destination("Nowhere", "MOVE")) is ObjectUnknownException) shouldBe true
        refusal(Destination("A", "Load cargo")).message shouldBe
            "transport order 'T', destination 1: operation 'Load cargo' at point 'A' must be MOVE or PARK"
        refusal(Destination("S", "Drill")).message shouldBe
            "transport order 'T', destination 1: operation 'Drill' is not allowed at location 'S' (type 'Station' allows Load cargo, Unload cargo)"
        refusal(Destination("S", "Unload cargo")).message shouldBe
            "transport order 'T', destination 1: no link of location 'S' allows operation 'Unload cargo'"
        shouldThrow<ObjectUnknownException> {
            create(TransportOrderCreation("T", listOf(Destination("A", "MOVE")), intendedVehicle = "Ghost"))
        }.message shouldBe "transport order 'T': unknown intended vehicle 'Ghost'"
        shouldThrow<ObjectUnknownException> {
            create(TransportOrderCreation("T", listOf(Destination("A", "MOVE")), dependencies = setOf("Missing")))
        }.message shouldBe "transport order 'T': unknown dependency 'Missing'"
    }

    test("NOP is allowed at any location") {
        create(TransportOrderCreation("T", listOf(Destination("S", "NOP")))).driveOrders.size shouldBe 1
    }
})
