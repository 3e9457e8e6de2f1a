package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderState

class IdleVehicleRechargingTest : FunSpec({
    val recharging = DispatcherConfiguration(parkIdleVehicles = false)

    /** Chargers C1 at B and C2 at G; V1 at D is two paths from C1 and three from C2. */
    fun chargers(v1: Vehicle = vehicle("V1", at = "D", energy = 50), vararg extra: Location) =
        FakeDispatchContext(plant(charger("C1", "B"), charger("C2", "G"), *extra)).apply { add(v1) }

    fun FakeDispatchContext.rechargeTargets() = created.map {
        it.intendedVehicle to
            it.driveOrders.single().destination.target
    }

    test("a degraded idle vehicle is sent to the closest charger, in the same run") {
        val context = chargers()

        context.dispatch(recharging)

        val order = context.created.single()
        order.name shouldBe "Recharge-01"
        order.type shouldBe CHARGE_ORDER_TYPE
        order.intendedVehicle shouldBe "V1"
        order.dispensable shouldBe true
        order.driveOrders.single().destination shouldBe Destination("C1", "CHARGE")
        context.assignedOrder("V1") shouldBe "Recharge-01"
    }

    test("a vehicle with good energy is not sent") {
        val context = chargers(vehicle("V1", at = "D", energy = 91))

        context.dispatch(recharging)

        context.created.shouldBeEmpty()
    }

    test("the recharge order of a vehicle with critical energy is not dispensable") {
        val context = chargers(vehicle("V1", at = "D", energy = 30))

        context.dispatch(recharging)

        context.created.single().dispensable shouldBe false
    }

    test("chargers that are occupied, targeted by another order or locked are skipped") {
        val occupied = chargers().apply { add(vehicle("V2", at = "B")) }
        val targeted = chargers().apply { add(order("Other", Destination("C1", "CHARGE"), intended = "V9")) }
        val locked = FakeDispatchContext(plant(charger("C1", "B", locked = true), charger("C2", "G")))
        locked.add(vehicle("V1", at = "D", energy = 50))

        listOf(occupied, targeted, locked).forEach { context ->
            context.dispatch(recharging)
            context.rechargeTargets() shouldContainExactly listOf("V1" to "C2")
        }
    }

    test("only locations whose type allows the vehicle's recharge operation qualify") {
        val fast = LocationType("Fast", allowedOperations = setOf("FAST_CHARGE"))
        val context = chargers(vehicle("V1", at = "D", energy = 50).copy(rechargeOperation = "FAST_CHARGE"))
        context.model = context.model.copy(
            locationTypes = context.model.locationTypes + fast,
            locations = context.model.locations + charger("F1", "H").copy(type = "Fast"),
        )

        context.dispatch(recharging)

        context.created.single().driveOrders.single().destination shouldBe Destination("F1", "FAST_CHARGE")
    }

    test("an assigned recharge location is the only choice") {
        val assigned = mapOf(DispatcherProperties.ASSIGNED_RECHARGE_LOCATION to "C2")
        val free = chargers(vehicle("V1", at = "D", energy = 50, properties = assigned))
        val occupied = chargers(vehicle("V1", at = "D", energy = 50, properties = assigned)).apply {
            add(vehicle("V2", at = "G"))
        }

        free.dispatch(recharging)
        occupied.dispatch(recharging)

        free.rechargeTargets() shouldContainExactly listOf("V1" to "C2")
        occupied.created.shouldBeEmpty()
    }

    test("a preferred recharge location is chosen while free, the closest otherwise") {
        val preferred = mapOf(DispatcherProperties.PREFERRED_RECHARGE_LOCATION to "C2")
        val free = chargers(vehicle("V1", at = "D", energy = 50, properties = preferred))
        val occupied = chargers(vehicle("V1", at = "D", energy = 50, properties = preferred)).apply {
            add(vehicle("V2", at = "G"))
        }

        free.dispatch(recharging)
        occupied.dispatch(recharging)

        free.rechargeTargets() shouldContainExactly listOf("V1" to "C2")
        occupied.rechargeTargets() shouldContainExactly listOf("V1" to "C1")
    }

    test("a vehicle must have been idle for the recharge delay") {
        val context = chargers()
        val dispatcher = context.dispatcher(recharging.copy(rechargeIdleVehiclesDelayMillis = 60_000))

        dispatcher.dispatch()
        context.created.shouldBeEmpty()

        context.clock.advance(60_000)
        dispatcher.dispatch()
        context.rechargeTargets() shouldContainExactly listOf("V1" to "C1")
    }

    test("two vehicles never get the same charger, and the emptier one goes first") {
        val context = FakeDispatchContext(plant(charger("C1", "B")))
        context.add(vehicle("V1", at = "C", energy = 50), vehicle("V2", at = "H", energy = 40))

        context.dispatch(recharging)

        context.rechargeTargets() shouldContainExactly listOf("V2" to "C1")
    }

    test("a charger with an occupied access point is reached through a free one") {
        val context = chargers(vehicle("V1", at = "D", energy = 50), charger("C3", "C", "E"))
        context.add(vehicle("V2", at = "C"))

        context.dispatch(recharging)

        val order = context.created.single()
        order.driveOrders.single().destination.target shouldBe "C3"
        order.properties[DispatcherProperties.RESOURCES_TO_AVOID] shouldBe "C"
        context.assignments.single().driveOrders.single().route?.finalDestinationPoint shouldBe "E"
    }

    test("no recharge order for a vehicle that refuses Charge orders, whose driver refuses, or that charges already") {
        val refusesType =
            chargers(
                vehicle(
                    "V1",
                    at = "D",
                    energy = 50,
                ).copy(acceptableOrderTypes = setOf(AcceptableOrderType("Transport", 0))),
            )
        val driverRefuses = chargers().apply { driver = { _, _ -> Explained.no("noCharging") } }
        val charging = chargers(vehicle("V1", at = "B", energy = 50, state = VehicleState.CHARGING))

        listOf(refusesType, driverRefuses, charging).forEach { context ->
            context.dispatch(recharging)
            context.created.shouldBeEmpty()
        }
    }

    test("a degraded vehicle is sent to recharge rather than to park, and only once") {
        val context = FakeDispatchContext(plant(charger("C1", "B"), park = setOf("H")))
        context.add(vehicle("V1", at = "D", energy = 50))
        val dispatcher = context.dispatcher(DispatcherConfiguration())

        dispatcher.dispatch()
        dispatcher.dispatch()

        context.created.map { it.type } shouldContainExactly listOf(CHARGE_ORDER_TYPE)
        context.orders.getValue("Recharge-01").state shouldBe TransportOrderState.BEING_PROCESSED
    }
})
