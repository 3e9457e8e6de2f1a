package org.ktcs.xmlchannels

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import java.net.ConnectException

class TcpServerTest : FunSpec({
    test("once close returns, nothing listens on the port any more") {
        repeat(200) {
            val server = TcpServer("test", "127.0.0.1", 0, maxConnections = 1, refusal = ByteArray(0))
            server.start { }
            server.close()

            shouldThrow<ConnectException> { HostClient.connect(server.port).close() }
        }
    }
})
