package org.ktcs.kernel.config

/** A configuration problem; the message is one line that names the key or the file. */
class ConfigException(message: String) : RuntimeException(message)
