plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    compileOnly(project(":extension-api"))
    compileOnly(libs.kotlinx.serialization.json)
    // kTCS's own lib/ holds Netty (Ktor's); the builtin broker adds only the MQTT codec
    compileOnly(libs.netty.handler)
    implementation(libs.netty.codec.mqtt)
    implementation(libs.hivemq.mqtt.client)
    implementation(libs.hivemq.community.edition.embedded)
    implementation(libs.jctools.core)
    implementation(libs.json.schema.validator)

    testImplementation(project(":kernel"))
    testImplementation(project(":adapters-loopback"))
}
