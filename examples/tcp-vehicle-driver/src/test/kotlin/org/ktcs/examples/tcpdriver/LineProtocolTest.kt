package org.ktcs.examples.tcpdriver

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain

class LineProtocolTest : FunSpec({
    test("a command names its id, point, operation and location") {
        LineProtocol.command(7, "Point-0001", "Load cargo", "Storage 01") shouldBe
            "COMMAND|7|Point-0001|Load cargo|Storage 01"
        LineProtocol.command(8, "Point-0002", "NOP", null) shouldBe "COMMAND|8|Point-0002|NOP|-"
    }

    test("a received line splits into name and fields, parameters into a map") {
        val message = LineProtocol.parse("EVENT|bumper|side=left|force=3\r")
        message shouldBe LineProtocol.Message("EVENT", listOf("bumper", "side=left", "force=3"))
        LineProtocol.parameters(message.fields.drop(1)) shouldBe mapOf("side" to "left", "force" to "3")
    }

    test("a field with the separator is refused with the field named") {
        shouldThrow<IllegalArgumentException> { LineProtocol.position("A|B") }.message shouldContain "'A|B'"
    }

    test("a parameter without '=' is refused") {
        shouldThrow<IllegalArgumentException> { LineProtocol.parameters(listOf("oops")) }.message shouldBe
            "expected key=value, got 'oops'"
    }
})
