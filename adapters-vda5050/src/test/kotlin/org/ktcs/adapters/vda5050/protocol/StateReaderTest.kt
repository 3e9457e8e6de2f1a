package org.ktcs.adapters.vda5050.protocol

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.matchers.types.shouldBeSameInstanceAs
import io.kotest.matchers.types.shouldNotBeSameInstanceAs

private fun state(headerId: Long, nodes: List<NodeState>, battery: Double = 80.0) = State(
    headerId, "2026-11-24T08:00:0${headerId % 10}Z", Vda.PROTOCOL_VERSION, "kTCS", "SIM-1", "o-1", 0,
    "Point-0001", 0, nodes, emptyList(), true, listOf(ActionState("a-1", "RUNNING", "pick")),
    BatteryState(battery, false), "AUTOMATIC", emptyList(), SafetyState("NONE", false),
)

private fun json(state: State) = Vda5050Json.encodeToString(State.serializer(), state).toByteArray()

private val route = listOf(NodeState("Point-0002", 2, true), NodeState("Point-0003", 4, false))

/**
 * A vehicle repeats its state every second, its node and edge states mostly unchanged: an array the vehicle's last
 * valid message had is neither checked nor decoded again, and everything else still is.
 */
class StateReaderTest : FunSpec({
    test("a repeated array is taken from the last message; the message reads as a whole") {
        val reader = StateReader(validate = true)
        val first = reader.read(json(state(1, route))).shouldBeInstanceOf<StateRead.Valid>().state
        val second = reader.read(json(state(2, route, battery = 79.5))).shouldBeInstanceOf<StateRead.Valid>().state
        second shouldBe state(2, route, battery = 79.5)
        second.nodeStates shouldBeSameInstanceAs first.nodeStates
        second.actionStates shouldBeSameInstanceAs first.actionStates
        val third = reader.read(json(state(3, route.drop(1)))).shouldBeInstanceOf<StateRead.Valid>().state
        third shouldBe state(3, route.drop(1))
        third.nodeStates shouldNotBeSameInstanceAs first.nodeStates
    }

    test("an element the last message's array had is reused; the new ones are checked and decoded, in order") {
        val reader = StateReader(validate = true)
        val longer = route + NodeState("Point-0004", 6, false)
        val first = reader.read(json(state(1, longer))).shouldBeInstanceOf<StateRead.Valid>().state
        // The vehicle passed Point-0002, and its horizon grew by one node.
        val next = longer.drop(1) + NodeState("Point-0005", 8, false)
        val second = reader.read(json(state(2, next))).shouldBeInstanceOf<StateRead.Valid>().state
        second shouldBe state(2, next)
        second.nodeStates[0] shouldBeSameInstanceAs first.nodeStates[1]
        second.nodeStates[1] shouldBeSameInstanceAs first.nodeStates[2]
        // A new element next to known ones is checked, and its problem names its place in the message as sent.
        val badNew = String(json(state(3, next.take(2) + NodeState("Point-0006", 10, false))))
            .replace("\"sequenceId\":10", "\"sequenceId\":\"ten\"")
        reader.read(badNew.toByteArray()).shouldBeInstanceOf<StateRead.Invalid>().problems.single() shouldStartWith
            "/nodeStates/2/sequenceId: "
    }

    test("what changed is checked, also next to repeated arrays; an invalid message is not remembered") {
        val reader = StateReader(validate = true)
        reader.read(json(state(1, route))).shouldBeInstanceOf<StateRead.Valid>()
        val badNode = String(json(state(2, route))).replace("\"sequenceId\":4", "\"sequenceId\":\"four\"")
        reader.read(badNode.toByteArray()).shouldBeInstanceOf<StateRead.Invalid>().problems.single() shouldStartWith
            "/nodeStates/1/sequenceId: "
        // The same broken array again: still checked, as no valid message had it.
        reader.read(badNode.replace("\"headerId\":2", "\"headerId\":3").toByteArray())
            .shouldBeInstanceOf<StateRead.Invalid>().problems shouldHaveSize 1
        val badMode = String(json(state(4, route))).replace("\"AUTOMATIC\"", "\"ASLEEP\"")
        reader.read(badMode.toByteArray()).shouldBeInstanceOf<StateRead.Invalid>().problems.single() shouldStartWith
            "/operatingMode: "
        reader.read(
            "{\"headerId\":".toByteArray(),
        ).shouldBeInstanceOf<StateRead.Invalid>().problems.single() shouldStartWith
            "not JSON: "
    }

    test("a changed value its bytes cannot vouch for is the validator's: escapes decoded, problems named") {
        val reader = StateReader(validate = true)
        reader.read(json(state(1, route))).shouldBeInstanceOf<StateRead.Valid>()
        val escaped = String(json(state(2, route))).replace("\"o-1\"", "\"o-\\u0032\"")
        reader.read(escaped.toByteArray()).shouldBeInstanceOf<StateRead.Valid>().state.orderId shouldBe "o-2"
        val outOfRange = String(json(state(3, route))).replace("\"batteryCharge\":80.0", "\"batteryCharge\":\"full\"")
        reader.read(outOfRange.toByteArray()).shouldBeInstanceOf<StateRead.Invalid>().problems.single() shouldStartWith
            "/batteryState/batteryCharge: "
        val fresh = route + NodeState("Pünkt-7", 6, false)
        reader.read(json(state(4, fresh))).shouldBeInstanceOf<StateRead.Valid>().state shouldBe state(4, fresh)
    }

    test("a field spelt as before is taken as read then; other fields, or the same named twice, are read whole") {
        val reader = StateReader(validate = true)
        reader.read(json(state(1, route))).shouldBeInstanceOf<StateRead.Valid>()
        // A message lacking a field the schema requires is read whole, and what it lacks is named.
        val withoutSafety = String(
            json(state(2, route)),
        ).replace(",\"safetyState\":{\"eStop\":\"NONE\",\"fieldViolation\":false}", "")
        withoutSafety shouldNotBe String(json(state(2, route)))
        reader.read(withoutSafety.toByteArray()).shouldBeInstanceOf<StateRead.Invalid>().problems.single() shouldContain
            "safetyState"
        val withoutErrors = String(json(state(2, route))).replace(",\"errors\":[]", "")
        withoutErrors shouldNotBe String(json(state(2, route)))
        reader.read(withoutErrors.toByteArray()).shouldBeInstanceOf<StateRead.Invalid>().problems.single() shouldContain
            "errors"
        // Named twice, the parser keeps the last: so it stays when only the first changes.
        val twice = { first: String -> String(json(state(3, route))).replaceFirst("{", "{\"orderId\":\"$first\",") }
        reader.read(twice("o-0").toByteArray()).shouldBeInstanceOf<StateRead.Valid>().state.orderId shouldBe "o-1"
        reader.read(twice("o-9").toByteArray()).shouldBeInstanceOf<StateRead.Valid>().state.orderId shouldBe "o-1"
        reader.read(json(state(4, route, battery = 12.0))).shouldBeInstanceOf<StateRead.Valid>().state shouldBe
            state(4, route, battery = 12.0)
    }
})
