package org.ktcs.build

/**
 * A small two-module build (`core`, and `app` on top of it) written for both Maven and Gradle, in agreement.
 * The drift tests change one text at a time and check that exactly that difference is reported.
 */
data class TwoModuleBuild(
    val rootPom: String = ROOT_POM,
    val appPom: String = APP_POM,
    val settings: String = """include("core", "app")""",
    val catalog: String = CATALOG,
    val conventions: String = CONVENTIONS,
    val appBuild: String = APP_BUILD,
) {
    fun differences(): List<String> = buildDifferences(
        MavenBuild(rootPom, mapOf("core" to CORE_POM, "app" to appPom)),
        GradleBuild(
            settings,
            catalog,
            mapOf("core" to """plugins { id("demo.conventions") }""", "app" to appBuild),
            mapOf("demo.conventions" to conventions),
        ),
    )

    companion object {
        val ROOT_POM = $$"""
            <project>
                <groupId>org.demo</groupId>
                <artifactId>demo-parent</artifactId>
                <version>1.0</version>
                <modules>
                    <module>core</module>
                    <module>app</module>
                </modules>
                <properties>
                    <ktor.version>3.5.1</ktor.version>
                    <kotest.version>6.2.4</kotest.version>
                    <surefire.version>3.6.1</surefire.version>
                </properties>
                <dependencyManagement>
                    <dependencies>
                        <dependency>
                            <groupId>io.ktor</groupId>
                            <artifactId>ktor-bom</artifactId>
                            <version>${ktor.version}</version>
                            <type>pom</type>
                            <scope>import</scope>
                        </dependency>
                        <dependency>
                            <groupId>io.kotest</groupId>
                            <artifactId>kotest-runner-junit5-jvm</artifactId>
                            <version>${kotest.version}</version>
                        </dependency>
                        <dependency>
                            <groupId>org.demo</groupId>
                            <artifactId>demo-core</artifactId>
                            <version>${project.version}</version>
                        </dependency>
                    </dependencies>
                </dependencyManagement>
                <dependencies>
                    <dependency>
                        <groupId>org.jetbrains.kotlin</groupId>
                        <artifactId>kotlin-stdlib</artifactId>
                    </dependency>
                    <dependency>
                        <groupId>io.kotest</groupId>
                        <artifactId>kotest-runner-junit5-jvm</artifactId>
                        <scope>test</scope>
                    </dependency>
                </dependencies>
                <build>
                    <plugins>
                        <plugin>
                            <artifactId>maven-surefire-plugin</artifactId>
                            <version>${surefire.version}</version>
                        </plugin>
                    </plugins>
                </build>
            </project>
        """

        val CORE_POM = "<project><artifactId>demo-core</artifactId></project>"

        val APP_POM = """
            <project>
                <artifactId>demo-app</artifactId>
                <dependencies>
                    <dependency>
                        <groupId>org.demo</groupId>
                        <artifactId>demo-core</artifactId>
                    </dependency>
                    <dependency>
                        <groupId>io.ktor</groupId>
                        <artifactId>ktor-server-core-jvm</artifactId>
                    </dependency>
                    <dependency>
                        <groupId>io.ktor</groupId>
                        <artifactId>ktor-server-test-host-jvm</artifactId>
                        <scope>test</scope>
                    </dependency>
                </dependencies>
            </project>
        """

        val CATALOG = """
            [versions]
            ktor = "3.5.1"
            kotest = "6.2.4"

            [libraries]
            ktor-server-core = { module = "io.ktor:ktor-server-core", version.ref = "ktor" }
            ktor-server-test-host = { group = "io.ktor", name = "ktor-server-test-host", version.ref = "ktor" }
            kotest-runner-junit5 = { module = "io.kotest:kotest-runner-junit5", version.ref = "kotest" } # a comment
        """

        val CONVENTIONS = """
            plugins {
                id("org.jetbrains.kotlin.jvm")
            }
            dependencies {
                testImplementation(libs.findLibrary("kotest-runner-junit5").get())
            }
        """

        val APP_BUILD = """
            plugins {
                id("demo.conventions")
            }
            dependencies {
                implementation(project(":core"))
                api(libs.ktor.server.core)
                // implementation(libs.ktor.server.cio)
                testImplementation(libs.ktor.server.test.host)
            }
        """
    }
}
