package org.ktcs.adapters.vda5050.broker

/** A retained message: the last one published with the retain flag to its topic. */
internal class Retained(val topic: String, val payload: ByteArray, val qos: Int)

/** The broker's retained messages, one per topic; only the broker's event loop uses them. */
internal class RetainedMessages {
    private val messages = HashMap<String, Retained>()

    /** Keeps [payload] as [topic]'s retained message; an empty payload clears it. */
    fun put(topic: String, payload: ByteArray, qos: Int) {
        if (payload.isEmpty()) messages.remove(topic) else messages[topic] = Retained(topic, payload, qos)
    }

    operator fun get(topic: String): Retained? = messages[topic]

    /** The retained messages [filter] matches: one look-up for a filter without wildcards, else a scan. */
    fun matching(filter: String): List<Retained> = if (TopicNames.hasWildcard(filter)) {
        messages.values.filter { TopicNames.matches(filter, it.topic) }
    } else {
        listOfNotNull(messages[filter])
    }
}
