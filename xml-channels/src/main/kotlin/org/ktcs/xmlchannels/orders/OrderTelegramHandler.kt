package org.ktcs.xmlchannels.orders

import org.ktcs.api.error.KernelException
import org.ktcs.api.model.XmlSafeText
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.service.TransportOrderService

/**
 * Creates the orders of one telegram through the kernel's services, one after the other, and answers each. An
 * order the kernel refuses gets a failed response with the kernel's reason; the others are created all the same.
 */
internal class OrderTelegramHandler(private val orders: TransportOrderService, private val scripts: ScriptFiles) {
    // An XML 1.1 telegram can carry characters (`&#x1;`) that an XML 1.0 receipt cannot echo.
    suspend fun handle(orderSet: OrderSetTO): ResponseSetTO =
        ResponseSetTO(orderSet.order.map { respond(it.copy(id = XmlSafeText.printable(it.id))) })

    private suspend fun respond(order: OrderTO): ResponseTO = when (order.type) {
        TRANSPORT -> create(order.id, TRANSPORT_RESPONSE) { order.toCreation() }
        TRANSPORT_SCRIPT -> runScript(order)
        else -> failed(order.id, TRANSPORT_RESPONSE, "unknown order type '${order.type}'")
    }

    private suspend fun runScript(order: OrderTO): ScriptResponseTO {
        val script = try {
            scripts.read(order.fileName ?: throw TelegramContentException("transportScript without fileName"))
        } catch (error: TelegramContentException) {
            return ScriptResponseTO(
                parsingSuccessful = false,
                id = order.id,
                reason = error.message?.let(XmlSafeText::printable),
            )
        }
        return ScriptResponseTO(parsingSuccessful = true, id = order.id, transport = runOrders(order.id, script))
    }

    /** With sequential dependencies each order depends on the one before; once one fails, the rest fail too. */
    private suspend fun runOrders(id: String, script: ScriptFileTO): List<TransportResponseTO> {
        var previous: TransportResponseTO? = null
        return script.order.map { scriptOrder ->
            val predecessor = previous?.takeIf { script.sequentialDependencies }
            val response = if (predecessor?.executionSuccessful == false) {
                failed(id, null, "an earlier order of this sequential script was not created")
            } else {
                create(id, null) { scriptOrder.toCreation(listOfNotNull(predecessor?.orderName)) }
            }
            response.also { previous = it }
        }
    }

    private suspend fun create(id: String, xsiType: String?, creation: () -> TransportOrderCreation) = try {
        TransportResponseTO(xsiType, true, orders.createTransportOrder(creation()).name, id)
    } catch (error: KernelException) {
        failed(id, xsiType, error.message ?: error.toString())
    } catch (error: TelegramContentException) {
        failed(id, xsiType, error.message ?: error.toString())
    }

    private fun failed(id: String, xsiType: String?, reason: String) =
        TransportResponseTO(
            xsiType,
            executionSuccessful = false,
            orderName = "",
            id = id,
            reason = XmlSafeText.printable(reason),
        )
}
