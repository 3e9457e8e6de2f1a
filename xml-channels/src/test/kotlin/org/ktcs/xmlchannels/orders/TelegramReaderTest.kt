package org.ktcs.xmlchannels.orders

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import java.io.ByteArrayInputStream
import java.io.InputStream

class TelegramReaderTest : FunSpec({
    test("stops at an empty line even when it arrives a byte at a time") {
        val input = OneByteAtATime("<tcsOrderSet/>\r\n\r\nignored".toByteArray())

        TelegramReader(limit = 100).read(input).decodeToString() shouldBe "<tcsOrderSet/>"
    }

    test("reads up to the end of the stream without an empty line") {
        TelegramReader(limit = 100).read("<tcsOrderSet/>\r\n".byteInputStream()).decodeToString() shouldBe
            "<tcsOrderSet/>\r\n"
    }

    test("a telegram exactly at the limit is read, one byte more is rejected") {
        TelegramReader(limit = 10).read("0123456789".byteInputStream()).size shouldBe 10
        shouldThrow<TelegramRejectedException> { TelegramReader(limit = 10).read("0123456789X".byteInputStream()) }
            .reason shouldBe "telegram longer than 10 bytes"
    }
})

private class OneByteAtATime(bytes: ByteArray) : InputStream() {
    private val input = ByteArrayInputStream(bytes)

    override fun read(): Int = input.read()

    override fun read(buffer: ByteArray, offset: Int, length: Int): Int = input.read(buffer, offset, minOf(length, 1))
}
