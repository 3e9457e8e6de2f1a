package org.ktcs.e2e

import java.nio.file.Files
import java.nio.file.Path

/** The checkout the tests run in: set by the build, or found by walking up to the launcher script. */
object RepositoryRoot {
    val path: Path by lazy {
        System.getProperty("ktcs.repositoryRoot")?.let { Path.of(it) }
            ?: generateSequence(Path.of("").toAbsolutePath()) { it.parent }
                .firstOrNull { Files.isRegularFile(it.resolve("ktcs")) }
            ?: error("cannot find the kTCS checkout above ${Path.of("").toAbsolutePath()}")
    }
}
