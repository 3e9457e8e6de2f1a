package org.ktcs.xmlchannels.orders

import com.fasterxml.jackson.core.exc.StreamReadException
import com.fasterxml.jackson.databind.JsonMappingException
import org.ktcs.api.service.TransportOrderService
import org.ktcs.xmlchannels.HostXml
import org.ktcs.xmlchannels.XmlChannelSettings
import org.slf4j.LoggerFactory
import java.io.IOException
import java.net.Socket
import javax.xml.stream.XMLStreamException

/**
 * The order channel's protocol on one connection: read one `tcsOrderSet` telegram, create its orders, answer with a
 * `tcsResponseSet`, close. A telegram that is too long, too slow, not well-formed or not a `tcsOrderSet` creates
 * nothing: the connection is closed with one warning in the log.
 */
internal class OrderChannelServer(orders: TransportOrderService, private val settings: XmlChannelSettings) {
    private val log = LoggerFactory.getLogger(OrderChannelServer::class.java)
    private val reader = TelegramReader(settings.inputLimit)
    private val handler = OrderTelegramHandler(orders, ScriptFiles(settings.scriptsDirectory))

    suspend fun serve(socket: Socket) {
        socket.soTimeout = settings.idleTimeout.inWholeMilliseconds.toInt()
        val orderSet = try {
            parse(reader.read(socket.getInputStream()))
        } catch (error: TelegramRejectedException) {
            return reject(socket, error.reason)
        } catch (error: IOException) {
            return reject(socket, "connection failed: ${error.message}")
        }
        val receipt = HostXml.write(handler.handle(orderSet)).toByteArray(Charsets.UTF_8)
        try {
            socket.getOutputStream().apply {
                write(receipt)
                flush()
            }
        } catch (error: IOException) {
            log.warn(
                "XML order channel: could not send the receipt to {}: {}",
                socket.remoteSocketAddress,
                error.message,
            )
        }
    }

    private fun reject(socket: Socket, reason: String) =
        log.warn(
            "XML order channel: closed the connection from {} without creating orders: {}",
            socket.remoteSocketAddress,
            reason,
        )

    private fun parse(bytes: ByteArray): OrderSetTO = try {
        val root = HostXml.wellFormedRootName(bytes)
        if (root != ORDER_SET) throw TelegramRejectedException("root element is '$root', not '$ORDER_SET'")
        HostXml.read(bytes)
    } catch (error: XMLStreamException) {
        throw TelegramRejectedException("malformed XML: ${firstLine(error.message)}")
    } catch (error: StreamReadException) {
        throw TelegramRejectedException("malformed XML: ${firstLine(error.originalMessage)}")
    } catch (error: JsonMappingException) {
        throw TelegramRejectedException("not a valid $ORDER_SET: missing or bad value at ${pathOf(error)}")
    }

    private fun pathOf(error: JsonMappingException) =
        error.path.joinToString("") { if (it.fieldName != null) "/${it.fieldName}" else "[${it.index + 1}]" }

    private fun firstLine(text: String?) = text.orEmpty().lineSequence().first()
}
