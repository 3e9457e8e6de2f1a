package org.ktcs.adapters.vda5050.broker

/** MQTT's rules for topic names (what a message is published to) and topic filters (what a client subscribes to). */
internal object TopicNames {
    /** A name to publish to: not empty, no wildcards, no NUL character. */
    fun isValidName(topic: String): Boolean =
        topic.isNotEmpty() && topic.none { it == '+' || it == '#' || it == '\u0000' }

    /** A filter: not empty; `+` only as a whole level; `#` only as the whole last level. */
    fun isValidFilter(filter: String): Boolean {
        if (filter.isEmpty() || filter.contains('\u0000')) return false
        val levels = filter.split('/')
        return levels.withIndex().all { (index, level) ->
            when {
                level.contains('#') -> level == "#" && index == levels.lastIndex
                level.contains('+') -> level == "+"
                else -> true
            }
        }
    }

    fun hasWildcard(filter: String): Boolean = filter.contains('+') || filter.contains('#')

    /** Whether [filter] matches [topic]; wildcards do not match a first level that begins with `$`. */
    fun matches(filter: String, topic: String): Boolean {
        val filterLevels = filter.split('/')
        val topicLevels = topic.split('/')
        if (topic.startsWith('$') && (filterLevels[0] == "+" || filterLevels[0] == "#")) return false
        for ((index, level) in filterLevels.withIndex()) {
            if (level == "#") return true
            if (index >= topicLevels.size) return false
            if (level != "+" && level != topicLevels[index]) return false
        }
        return filterLevels.size == topicLevels.size
    }
}
