plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":api"))
    implementation(libs.ktor.client.core)
    implementation(libs.ktor.client.cio)
    implementation(libs.ktor.client.websockets)
    implementation(libs.ktor.client.content.negotiation)
    implementation(libs.ktor.serialization.kotlinx.json)
    implementation(libs.kotlinx.serialization.json)
    implementation(libs.kotlinx.coroutines.core)
    testImplementation(project(":kernel"))
    testImplementation(project(":adapters-loopback"))
}
