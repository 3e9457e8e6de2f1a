package org.ktcs.e2e.plant

import org.ktcs.e2e.RepositoryRoot
import java.nio.file.Files
import java.nio.file.Path

/** The packaged example extensions, as the build leaves them (e2e-tests depends on their modules for the order). */
object ExampleJars {
    val tcpVehicleDriver: Path get() = jar("tcp-vehicle-driver")
    val overviewPanelTheme: Path get() = jar("overview-panel-theme")

    private fun jar(example: String): Path {
        val jar = RepositoryRoot.path.resolve("examples/$example/target/ktcs-example-$example.jar")
        check(Files.isRegularFile(jar)) {
            "the example extension jar $jar is missing: build it first, e.g. ./mvnw -B package -DskipTests " +
                "-pl examples/$example -am"
        }
        return jar
    }
}
