package org.ktcs.kernel.scheduling

/** A growable stack of ints, to keep the check free of boxing. */
internal class IntStack {
    @PublishedApi internal var items = IntArray(8)

    @PublishedApi internal var size = 0

    fun push(value: Int) {
        if (size == items.size) items = items.copyOf(size * 2)
        items[size++] = value
    }

    fun pop(): Int = items[--size]

    fun clear() {
        size = 0
    }

    fun isNotEmpty(): Boolean = size > 0

    inline fun forEach(action: (Int) -> Unit) {
        for (i in 0 until size) action(items[i])
    }
}

/** A growable first-in-first-out queue of ints. */
internal class IntQueue {
    private var items = IntArray(8)
    private var head = 0
    private var tail = 0

    fun push(value: Int) {
        if (tail == items.size) {
            if (head > 0) {
                items.copyInto(items, 0, head, tail)
                tail -= head
                head = 0
            }
            if (tail == items.size) items = items.copyOf(items.size * 2)
        }
        items[tail++] = value
    }

    fun take(): Int {
        val value = items[head++]
        if (head == tail) {
            head = 0
            tail = 0
        }
        return value
    }

    fun isNotEmpty(): Boolean = head < tail
}
