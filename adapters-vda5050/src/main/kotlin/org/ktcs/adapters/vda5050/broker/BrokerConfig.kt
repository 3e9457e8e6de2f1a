package org.ktcs.adapters.vda5050.broker

/**
 * How the builtin broker is set up: where it listens, the credentials a client must give ([username] empty: none)
 * and the largest packet it takes.
 */
data class BrokerConfig(
    val bindAddress: String = "127.0.0.1",
    val port: Int = 1883,
    val username: String = "",
    val password: String = "",
    val maxPacketBytes: Int = DEFAULT_MAX_PACKET_BYTES,
) {
    companion object {
        /** 1 MiB: a VDA 5050 state message of a long order is tens of kilobytes. */
        const val DEFAULT_MAX_PACKET_BYTES = 1 shl 20
    }
}
