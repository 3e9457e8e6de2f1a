plugins {
    id("ktcs.kotlin-jvm")
    application
}

application {
    mainClass.set("org.ktcs.kernel.app.MainKt")
}

// api(...) plays Maven's compile scope: the extension modules (loopback, web overview, XML channels) build on
// the kernel and see these too, as they do in Maven.
dependencies {
    api(project(":api"))
    api(project(":extension-api"))
    api(libs.kotlinx.coroutines.core)
    api(libs.kotlinx.serialization.json)
    api(libs.koin.core)
    api(libs.koin.logger.slf4j)
    api(libs.ktor.server.core)
    api(libs.ktor.server.cio)
    api(libs.ktor.server.netty)
    api(libs.ktor.server.content.negotiation)
    api(libs.ktor.serialization.kotlinx.json)
    api(libs.ktor.server.status.pages)
    api(libs.ktor.server.websockets)
    api(libs.jgrapht.core)
    api(libs.jackson.dataformat.xml)
    api(libs.jackson.module.parameter.names)
    api(libs.jackson.dataformat.yaml)
    api(libs.logback.classic)
    api(libs.sqlite.jdbc)
    api(libs.postgresql)
    api(libs.flyway.core)
    api(libs.flyway.database.postgresql)
    runtimeOnly(libs.swagger.ui)
    runtimeOnly(variantOf(libs.netty.transport.native.epoll) { classifier("linux-x86_64") })

    testImplementation(libs.mockk)
    testImplementation(libs.ktor.server.test.host)
    testImplementation(libs.swagger.parser)
    testImplementation(libs.json.schema.validator)
}

// As kernel/pom.xml's exclusion on ktor-server-core: kTCS runs without kotlin-reflect (with it on the class path,
// every typeOf() at start-up builds full reflection descriptors). Tests get it from Kotest and MockK.
configurations.named("runtimeClasspath") {
    exclude(group = "org.jetbrains.kotlin", module = "kotlin-reflect")
}
