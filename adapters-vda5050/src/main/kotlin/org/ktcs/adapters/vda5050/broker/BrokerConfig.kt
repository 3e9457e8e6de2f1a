package org.ktcs.adapters.vda5050.broker

/**
 * How the builtin broker is set up: where it listens, the credentials a client must give ([username] empty: none),
 * the largest packet it takes and how long its thread pauses to read what arrives meanwhile in one go
 * ([BatchingSelect]).
 */
data class BrokerConfig(
    val bindAddress: String = "127.0.0.1",
    val port: Int = 1883,
    val username: String = "",
    val password: String = "",
    val maxPacketBytes: Int = DEFAULT_MAX_PACKET_BYTES,
    val batchMillis: Long = DEFAULT_BATCH_MILLIS,
) {
    companion object {
        /** 1 MiB: a VDA 5050 state message of a long order is tens of kilobytes. */
        const val DEFAULT_MAX_PACKET_BYTES = 1 shl 20

        /** 5 ms: a fifth of the wake-ups with 100 vehicles, well within the 20 ms a message may take. */
        const val DEFAULT_BATCH_MILLIS = 5L
    }
}
