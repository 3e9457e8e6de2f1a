package org.ktcs.kernel.persistence

/**
 * A plant-model file could not be read or written. The message is one line that names the file and, where known,
 * the line and column of the problem, e.g. `plant.xml:12:9: invalid value "FOO" for attribute "type" of <point>`.
 */
class ModelFileException(message: String, cause: Throwable? = null) : RuntimeException(message, cause)
