package org.ktcs.xmlchannels.orders

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.ktor.utils.io.ByteChannel
import io.ktor.utils.io.ByteReadChannel
import io.ktor.utils.io.writeByte
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch

class TelegramReaderTest : FunSpec({
    test("stops at an empty line even when it arrives a byte at a time") {
        val telegram = coroutineScope {
            val input = ByteChannel()
            launch {
                "<tcsOrderSet/>\r\n\r\n".toByteArray().forEach {
                    input.writeByte(it)
                    input.flush()
                }
            }
            TelegramReader(limit = 100).read(input).decodeToString().also { input.cancel(null) }
        }

        telegram shouldBe "<tcsOrderSet/>"
    }

    test("reads up to the end of the stream without an empty line") {
        TelegramReader(limit = 100).read(ByteReadChannel("<tcsOrderSet/>\r\n")).decodeToString() shouldBe
            "<tcsOrderSet/>\r\n"
    }

    test("a telegram exactly at the limit is read, one byte more is rejected") {
        TelegramReader(limit = 10).read(ByteReadChannel("0123456789")).size shouldBe 10
        shouldThrow<TelegramRejectedException> { TelegramReader(limit = 10).read(ByteReadChannel("0123456789X")) }
            .reason shouldBe "telegram longer than 10 bytes"
    }
})
