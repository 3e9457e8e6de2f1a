package org.ktcs.kernel.app

import sun.misc.Signal
import java.util.concurrent.CountDownLatch

/**
 * Waits for Ctrl-C (SIGINT) or SIGTERM. Handling the signals ourselves, instead of relying on a shutdown hook,
 * lets the kernel stop in order and the process exit with code 0. The handlers are installed before the kernel
 * starts, so a signal that arrives while it is starting is not lost either.
 */
class ShutdownSignal private constructor() {
    private val latch = CountDownLatch(1)

    fun await() {
        latch.await()
    }

    /** Ends [await] as a signal would, e.g. for `DELETE /v1/kernel`. */
    fun request() {
        latch.countDown()
    }

    companion object {
        fun install(): ShutdownSignal = ShutdownSignal().also { signal ->
            listOf("INT", "TERM").forEach { name -> Signal.handle(Signal(name)) { signal.latch.countDown() } }
        }
    }
}
