# MHB_SANITIZE=address,undefined or MHB_SANITIZE=thread builds everything with those sanitizers.
if(MHB_SANITIZE)
    add_compile_options(-fsanitize=${MHB_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
    add_link_options(-fsanitize=${MHB_SANITIZE})
endif()
