package org.ktcs.xmlchannels.orders

import com.fasterxml.jackson.core.exc.StreamReadException
import com.fasterxml.jackson.databind.JsonMappingException
import io.ktor.utils.io.writeFully
import kotlinx.coroutines.withTimeoutOrNull
import org.ktcs.api.model.XmlSafeText
import org.ktcs.api.service.TransportOrderService
import org.ktcs.xmlchannels.Connection
import org.ktcs.xmlchannels.HostXml
import org.ktcs.xmlchannels.XmlChannelSettings
import org.slf4j.LoggerFactory
import java.io.IOException
import javax.xml.stream.XMLStreamException

/**
 * The order channel's protocol on one connection: read one `tcsOrderSet` telegram, create its orders, answer with a
 * `tcsResponseSet`, close. A telegram that is too long, not complete by its deadline, not well-formed or not a
 * `tcsOrderSet` creates nothing: the connection is closed with one warning in the log. Nothing a telegram holds can
 * fail more than its own connection.
 */
internal class OrderChannelServer(orders: TransportOrderService, private val settings: XmlChannelSettings) {
    private val log = LoggerFactory.getLogger(OrderChannelServer::class.java)
    private val reader = TelegramReader(settings.inputLimit)
    private val handler = OrderTelegramHandler(orders, ScriptFiles(settings.scriptsDirectory))

    suspend fun serve(connection: Connection) {
        val deadline = settings.idleTimeout
        val orderSet = try {
            val bytes = withTimeoutOrNull(deadline) { reader.read(connection.input) }
                ?: return reject(connection, "telegram not complete within $deadline")
            parse(bytes)
        } catch (error: TelegramRejectedException) {
            return reject(connection, error.reason)
        } catch (error: IOException) {
            return reject(connection, "connection failed: ${error.message}")
        }
        val receipt = HostXml.write(handler.handle(orderSet)).toByteArray(Charsets.UTF_8)
        val sent = withTimeoutOrNull(deadline) {
            try {
                connection.output.writeFully(receipt)
                connection.output.flush()
                true
            } catch (error: IOException) {
                false.also { couldNotSend(connection, error.message) }
            }
        }
        if (sent == null) couldNotSend(connection, "the client did not read it within $deadline")
    }

    private fun couldNotSend(connection: Connection, reason: String?) =
        log.warn("XML order channel: could not send the receipt to {}: {}", connection.address, reason)

    private fun reject(connection: Connection, reason: String) =
        log.warn(
            "XML order channel: closed the connection from {} without creating orders: {}",
            connection.address,
            XmlSafeText.printable(reason),
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
