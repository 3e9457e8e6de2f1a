package org.ktcs.kernel.web.ws

import io.ktor.server.routing.Route
import io.ktor.server.websocket.webSocket
import org.ktcs.api.service.KernelServices

/**
 * `/v1/ws`: kTCS's live WebSocket (see the README for the protocol). Upgrades from pages of other origins are
 * refused by [org.ktcs.kernel.web.plugins.CrossSiteGuard]; [live] lets a shutdown say goodbye to every client.
 */
fun Route.webSocketRoutes(services: KernelServices, bufferSize: Int, live: LiveWebSockets = LiveWebSockets()) {
    // One set of encoded states for every session: a state is encoded once however many clients follow it.
    val encoded = EncodedObjects()
    webSocket("/ws") { live.track(this) { WsSession(this, services, bufferSize, encoded).run() } }
}
