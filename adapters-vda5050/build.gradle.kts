plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    compileOnly(project(":kernel"))
    implementation(libs.hivemq.mqtt.client)
    implementation(libs.hivemq.community.edition.embedded)
    implementation(libs.jctools.core)
    implementation(libs.json.schema.validator)

    testImplementation(project(":adapters-loopback"))
}
