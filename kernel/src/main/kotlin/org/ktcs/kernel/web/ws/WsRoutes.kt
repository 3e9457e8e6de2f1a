package org.ktcs.kernel.web.ws

import io.ktor.server.routing.Route
import io.ktor.server.websocket.webSocket
import org.ktcs.api.service.KernelServices

/** `/v1/ws`: kTCS's live WebSocket (see the README for the protocol). */
fun Route.webSocketRoutes(services: KernelServices, bufferSize: Int) {
    webSocket("/ws") { WsSession(this, services, bufferSize).run() }
}
