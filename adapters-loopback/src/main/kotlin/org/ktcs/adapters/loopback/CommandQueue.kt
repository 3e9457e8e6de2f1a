package org.ktcs.adapters.loopback

import org.ktcs.api.driver.MovementCommand

/** The driver's command queue as the simulation sees it. */
internal interface CommandQueue {
    /** Commands sent and not yet reported back, oldest first; the oldest is the one being carried out. */
    val pending: List<MovementCommand>

    fun executed(command: MovementCommand)

    fun failed(command: MovementCommand)
}
