package org.ktcs.adapters.vda5050.broker

/**
 * What the broker keeps of a client id: its subscriptions and, while it is connected, its [connection]. A
 * [persistent] session (MQTT 3.1.1 clean session 0, MQTT 5 a session expiry interval above 0) keeps its subscriptions
 * while the client is away, until kTCS stops; messages published meanwhile are not kept for it.
 */
internal class Session(val clientId: String, val persistent: Boolean) {
    /** The topic filters subscribed to, with their granted QoS. */
    val filters = HashMap<String, Int>()

    var connection: ClientConnection? = null
}
