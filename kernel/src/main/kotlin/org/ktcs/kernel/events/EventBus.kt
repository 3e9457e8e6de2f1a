package org.ktcs.kernel.events

import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.channels.ReceiveChannel
import org.ktcs.api.event.KernelEvent
import org.ktcs.kernel.context.KernelContext
import java.util.concurrent.CopyOnWriteArrayList

/**
 * Distributes kernel events, in the order they are published (always from the kernel context).
 *
 * Kernel components listen synchronously ([listen]): they react before the next event is published. Everybody else
 * ([subscribe]: web clients, XML status channel, tests) gets a bounded buffer of its own; one that falls too far
 * behind is cut off with [SubscriberTooSlowException] instead of slowing the kernel or the other subscribers, and
 * can subscribe again and start from a fresh snapshot.
 *
 * Every change of kernel state is published here, so with the kernel's [context] the bus also checks that changes
 * happen in that context: with JVM assertions on (`-ea`, as in every test run) a publish from another thread fails.
 */
class EventBus(private val context: KernelContext? = null) : KernelEvents {
    private val listeners = CopyOnWriteArrayList<(KernelEvent) -> Unit>()
    private val subscribers = CopyOnWriteArrayList<Channel<KernelEvent>>()

    // Confined to the kernel context, like every publish.
    private val pending = ArrayDeque<KernelEvent>()
    private var delivering = false

    /** Calls [listener] for every event, in the kernel context, before the event reaches subscribers. */
    override fun listen(listener: (KernelEvent) -> Unit) {
        listeners += listener
    }

    /** A new subscription that receives every event published from now on, buffering up to [capacity]. */
    override fun subscribe(capacity: Int): ReceiveChannel<KernelEvent> {
        val channel = Channel<KernelEvent>(capacity)
        channel.invokeOnClose { subscribers.remove(channel) }
        subscribers += channel
        return channel
    }

    /**
     * With JVM assertions on (`-ea`, as in every test run), fails when kernel state is changed outside the kernel
     * context: the pools, the plant state and the vehicle controllers call it where they change, [publish] for every
     * event. [change] names the change for the error.
     */
    fun assertConfined(change: () -> Any) {
        assert(context?.isInKernelContext() != false) {
            "kernel state changed outside the kernel context (thread ${Thread.currentThread().name}): ${change()}"
        }
    }

    /** How many subscriptions are open now (each wakes its reader's thread for nearly every event). */
    override val subscriberCount: Int get() = subscribers.size

    /**
     * Publishes [event]. An event published by a listener while another is being delivered waits until that one
     * has reached everybody, so every listener and subscriber sees all events in the same order.
     *
     * A listener that throws does not stop delivery: the other listeners and the subscribers still get this event
     * and the ones queued behind it, in order; then the first failure is thrown to the publisher (later ones are
     * attached to it as suppressed), since a failing kernel listener is a defect that must not go unnoticed.
     */
    fun publish(event: KernelEvent) {
        assertConfined { event }
        pending.addLast(event)
        if (delivering) return
        delivering = true
        var failure: Throwable? = null
        try {
            while (pending.isNotEmpty()) {
                deliver(pending.removeFirst()) { error -> failure?.addSuppressed(error) ?: run { failure = error } }
            }
        } finally {
            delivering = false
        }
        failure?.let { throw it }
    }

    private fun deliver(event: KernelEvent, onFailure: (Throwable) -> Unit) {
        listeners.forEach { listener ->
            try {
                listener(event)
            } catch (error: Exception) {
                onFailure(error)
            }
        }
        subscribers.forEach { channel ->
            val sent = channel.trySend(event)
            if (sent.isFailure && !sent.isClosed) {
                channel.close(SubscriberTooSlowException())
            }
        }
    }

    companion object {
        const val DEFAULT_CAPACITY = 10_000
    }
}

/** A subscriber fell so far behind that it missed events; it should subscribe again and re-read the state. */
class SubscriberTooSlowException : RuntimeException(
    "event subscriber too slow: its buffer overflowed and events were lost",
)
