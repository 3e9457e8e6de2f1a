package org.ktcs.adapters.vda5050.broker

import io.netty.buffer.ByteBuf
import io.netty.channel.ChannelHandlerContext
import io.netty.channel.ChannelInboundHandlerAdapter

/**
 * Reads each packet's length from its fixed header as the bytes arrive and calls [oversize] with it (passing nothing
 * more on) as soon as one is over [maxBytes]: Netty's MQTT decoder would first buffer the whole packet, up to 256 MB,
 * before it compared. Everything else passes through unchanged.
 */
internal class PacketSizeGuard(
    private val maxBytes: Int,
    private val oversize: (ChannelHandlerContext, Long) -> Unit,
) : ChannelInboundHandlerAdapter() {
    private var bodyLeft = 0L // bytes of the current packet after its fixed header still to pass
    private var headerBytes = 0 // bytes of the current fixed header read so far
    private var length = 0L
    private var multiplier = 1L
    private var stopped = false

    override fun channelRead(ctx: ChannelHandlerContext, msg: Any) {
        val bytes = msg as ByteBuf
        if (!stopped && !admits(bytes)) {
            stopped = true
            bytes.release()
            oversize(ctx, length)
            return
        }
        if (!stopped) ctx.fireChannelRead(bytes) else bytes.release()
    }

    private fun admits(bytes: ByteBuf): Boolean {
        var index = bytes.readerIndex()
        val end = bytes.writerIndex()
        while (index < end) {
            if (bodyLeft > 0) {
                val skipped = minOf(bodyLeft, (end - index).toLong())
                index += skipped.toInt()
                bodyLeft -= skipped
                continue
            }
            val byte = bytes.getByte(index++).toInt()
            if (headerBytes++ == 0) {
                length = 0
                multiplier = 1
                continue
            }
            length += (byte and LENGTH_BITS) * multiplier
            multiplier *= LENGTH_BASE
            // A length longer than four bytes is malformed: the decoder says so.
            if (byte and MORE_BIT == 0 || headerBytes >= MAX_HEADER_BYTES) {
                if (length > maxBytes) return false
                bodyLeft = length
                headerBytes = 0
            }
        }
        return true
    }

    private companion object {
        const val LENGTH_BITS = 0x7F
        const val MORE_BIT = 0x80
        const val LENGTH_BASE = 128L
        const val MAX_HEADER_BYTES = 5
    }
}
