package org.ktcs.extension.config

/** A configuration problem; the message is one line that names the key or the file. */
public class ConfigException(message: String) : RuntimeException(message)
