package org.ktcs.adapters.vda5050.broker

/**
 * The subscriptions, as a tree of topic levels: matching a published topic walks its levels (and the `+` and `#`
 * branches beside them), so the cost of a message is its topic's depth, not the number of subscriptions. Only the
 * broker's event loop uses it.
 */
internal class TopicTree {
    private class Node {
        val children = HashMap<String, Node>(CHILDREN)
        val subscribers = HashMap<Session, Int>(CHILDREN)

        fun isEmpty() = children.isEmpty() && subscribers.isEmpty()
    }

    private val root = Node()

    /** Subscribes [session] to [filter] with the granted [qos] (replacing an earlier grant for the same filter). */
    fun add(filter: String, session: Session, qos: Int) {
        var node = root
        for (level in filter.split('/')) node = node.children.getOrPut(level, ::Node)
        node.subscribers[session] = qos
    }

    /** Removes [session]'s subscription to [filter]; true if there was one. */
    fun remove(filter: String, session: Session): Boolean {
        val path = ArrayList<Pair<Node, String>>()
        var node = root
        for (level in filter.split('/')) {
            path += node to level
            node = node.children[level] ?: return false
        }
        val removed = node.subscribers.remove(session) != null
        for ((parent, level) in path.asReversed()) {
            val child = parent.children[level] ?: break
            if (!child.isEmpty()) break
            parent.children.remove(level)
        }
        return removed
    }

    /** Calls [visit] with every subscription matching [topic]: the session and its granted QoS. */
    fun forEachMatch(topic: String, visit: (Session, Int) -> Unit) {
        match(root, topic.split('/'), 0, topic.startsWith('$'), visit)
    }

    private fun match(node: Node, levels: List<String>, index: Int, dollar: Boolean, visit: (Session, Int) -> Unit) {
        val wildcards = index > 0 || !dollar
        // "a/#" matches "a" as well as everything below it.
        if (wildcards) node.children["#"]?.subscribers?.forEach(visit)
        if (index == levels.size) {
            node.subscribers.forEach(visit)
            return
        }
        node.children[levels[index]]?.let { match(it, levels, index + 1, dollar, visit) }
        if (wildcards) node.children["+"]?.let { match(it, levels, index + 1, dollar, visit) }
    }

    private companion object {
        const val CHILDREN = 2
    }
}
