package org.ktcs.adapters.vda5050.protocol

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import io.kotest.matchers.types.shouldBeInstanceOf

/** One parse per message: the schema checks the parsed tree, and the driver decodes that same tree. */
class MessageValidatorTest : FunSpec({
    val connection = """{"headerId":3,"timestamp":"2026-11-24T08:00:00Z","version":"2.0.0","manufacturer":"kTCS",""" +
        """"serialNumber":"SIM-1","connectionState":"ONLINE"}"""

    test("a valid message comes back as the tree the driver decodes") {
        val json = MessageValidator.check(IncomingTopic.CONNECTION, connection.toByteArray())
            .shouldBeInstanceOf<Checked.Valid>().json
        Vda5050Json.decodeFromJsonElement(Connection.serializer(), json) shouldBe
            Connection(3, "2026-11-24T08:00:00Z", "2.0.0", "kTCS", "SIM-1", "ONLINE")
    }

    test("a message that breaks the schema, and one that is not JSON, say what is wrong") {
        val broken = connection.replace("\"ONLINE\"", "\"SLEEPING\"")
        MessageValidator.check(IncomingTopic.CONNECTION, broken.toByteArray())
            .shouldBeInstanceOf<Checked.Invalid>().problems.single() shouldStartWith "/connectionState: "
        MessageValidator.check(IncomingTopic.CONNECTION, "{\"headerId\":".toByteArray())
            .shouldBeInstanceOf<Checked.Invalid>().problems.single() shouldStartWith "not JSON: "
        MessageValidator.problems(IncomingTopic.CONNECTION, connection) shouldContainExactly emptyList()
    }
})
